// load_plugin() on real plugin files: a good one, and one broken in each way the loader refuses.
// Every failure must name the file and say what is wrong.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "facet/framework/plugin_loader.hpp"
#include "facet/types/images.hpp"
#include "test_support.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// Loads one test plugin that must fail, and returns the reason.
std::string failure_reason(const fs::path& file) {
  Registry registry;
  EXPECT_FALSE(load_plugin(file, registry));
  EXPECT_TRUE(registry.plugins().empty());
  EXPECT_TRUE(registry.stage_names().empty());
  if (registry.failures().size() != 1u) {
    ADD_FAILURE() << "expected one failure, got:\n" << test::describe_failures(registry);
    return {};
  }
  EXPECT_EQ(registry.failures()[0].file, file);
  return registry.failures()[0].reason;
}

std::string failure_reason_of_case(const std::string& test_case) {
  return failure_reason(test::test_plugin_file(test_case));
}

TEST(LoadPlugin, GoodPluginRegistersItsStageAndDescribesItself) {
  Registry registry;
  const auto file = test::test_plugin_file("good");
  ASSERT_TRUE(load_plugin(file, registry)) << test::describe_failures(registry);
  EXPECT_TRUE(registry.failures().empty());
  ASSERT_EQ(registry.plugins().size(), 1u);
  const auto& info = *registry.plugins()[0];
  EXPECT_EQ(info.file, file);
  EXPECT_EQ(info.name, "good");
  EXPECT_EQ(info.version, "1.2.3");
  EXPECT_EQ(info.sdk_version, FACET_SDK_VERSION_STRING);
  EXPECT_EQ(info.toolchain, sdk_toolchain_fingerprint());
  EXPECT_EQ(info.stages, std::vector<std::string>{"test.constant"});

  const StageEntry* entry = registry.find("test.constant");
  ASSERT_NE(entry, nullptr);
  EXPECT_EQ(entry->plugin->name, "good");
  EXPECT_NE(entry->library, nullptr) << "stages must pin their plugin's library";
  ASSERT_NE(entry->spec.find_param("value"), nullptr);
  EXPECT_TRUE(static_cast<bool>(entry->spec.factory()));
}

TEST(LoadPlugin, StageFromAPluginRunsAndOutlivesTheRegistry) {
  std::unique_ptr<Stage> stage;
  std::unique_ptr<StageSpec> spec;
  {
    Registry registry;
    ASSERT_TRUE(load_plugin(test::test_plugin_file("good"), registry));
    const StageEntry* entry = registry.find("test.constant");
    ASSERT_NE(entry, nullptr);
    spec = std::make_unique<StageSpec>(entry->spec);
    Params params = spec->default_params();
    params.set("value", std::int64_t{7});
    stage = spec->factory()(params);
  }
  ASSERT_NE(stage, nullptr);
  ProcessContext ctx(*spec, "constant");
  ctx.begin_frame(0);
  stage->process(ctx);
  const auto* image = ctx.outputs()[0].get_if<DepthImage>();
  ASSERT_NE(image, nullptr) << "packet type key from the plugin must match the host's";
  EXPECT_EQ(image->depth.at<std::uint16_t>(1, 2), 7);
}

TEST(LoadPlugin, GoodPluginContributesItsDoctorSectionsInOrder) {
  Registry registry;
  ASSERT_TRUE(load_plugin(test::test_plugin_file("good"), registry))
      << test::describe_failures(registry);
  const auto& sections = registry.diagnostics();
  ASSERT_EQ(sections.size(), 2u);
  EXPECT_EQ(sections[0].section.title, "Test sensor");
  EXPECT_EQ(sections[1].section.title, "Test bus");
  for (const auto& entry : sections) {
    EXPECT_EQ(entry.plugin->name, "good");
    EXPECT_NE(entry.library, nullptr) << "a section's code lives in its plugin: it must pin it";
    ASSERT_TRUE(static_cast<bool>(entry.section.report));
  }
  // The reports run in the host, with the plugin's code, when asked (not at load).
  EXPECT_THAT(sections[0].section.report(), HasSubstr("test://0"));
  EXPECT_THROW(sections[1].section.report(), std::runtime_error);
}

TEST(LoadPlugin, AFailedPluginContributesNoDoctorSection) {
  Registry registry;
  EXPECT_FALSE(load_plugin(test::test_plugin_file("throwing"), registry));
  EXPECT_TRUE(registry.diagnostics().empty());
}

TEST(LoadPlugin, LoadingTheSameFileTwiceReportsTheStageConflict) {
  Registry registry;
  const auto file = test::test_plugin_file("good");
  ASSERT_TRUE(load_plugin(file, registry));
  load_plugin(file, registry);
  ASSERT_EQ(registry.failures().size(), 1u);
  EXPECT_THAT(registry.failures()[0].reason, HasSubstr("test.constant"));
}

TEST(LoadPlugin, LibraryWithoutEntrySymbolIsNotAPlugin) {
  EXPECT_EQ(failure_reason_of_case("no_entry"),
            "not a facet plugin: no exported symbol 'facet_plugin_entry'");
}

TEST(LoadPlugin, UndefinedSymbolIsReportedAtLoadTimeWithItsName) {
  const auto reason = failure_reason_of_case("undefined_symbol");
  EXPECT_THAT(reason, HasSubstr("cannot load"));
  EXPECT_THAT(reason, HasSubstr("undefined symbol"));
  EXPECT_THAT(reason, HasSubstr("facet_test_symbol_defined_nowhere"));
  EXPECT_THAT(reason, HasSubstr("libfacet_undefined_symbol.so"));
}

TEST(LoadPlugin, WrongAbiVersionIsRefusedBeforeRegistration) {
  // The broken plugins with a hand-written header abort in register_stages: reaching this
  // assertion at all shows that their C++ was never called.
  EXPECT_EQ(failure_reason_of_case("wrong_abi"),
            "ABI version mismatch: plugin has 999, host expects " +
                std::to_string(FACET_PLUGIN_ABI_VERSION));
}

TEST(LoadPlugin, WrongMagicIsRefused) {
  const auto reason = failure_reason_of_case("bad_magic");
  EXPECT_THAT(reason, HasSubstr("not a facet plugin header"));
  EXPECT_THAT(reason, HasSubstr("0x12345678"));
}

TEST(LoadPlugin, TruncatedHeaderIsRefused) {
  EXPECT_THAT(failure_reason_of_case("short_header"),
              HasSubstr("plugin header too small: plugin has 16"));
}

TEST(LoadPlugin, WrongSdkMinorVersionIsRefusedWithBothVersions) {
  const auto reason = failure_reason_of_case("wrong_sdk_minor");
  const auto plugin_version = std::to_string(FACET_SDK_VERSION_MAJOR) + "." +
                              std::to_string(FACET_SDK_VERSION_MINOR + 1) + "." +
                              std::to_string(FACET_SDK_VERSION_PATCH);
  EXPECT_THAT(reason, HasSubstr("SDK version mismatch"));
  EXPECT_THAT(reason, HasSubstr("plugin was built with SDK " + plugin_version));
  EXPECT_THAT(reason, HasSubstr(std::string("host has SDK ") + FACET_SDK_VERSION_STRING));
}

TEST(LoadPlugin, WrongToolchainIsRefusedWithBothFingerprints) {
  const auto reason = failure_reason_of_case("wrong_toolchain");
  EXPECT_THAT(reason, HasSubstr("toolchain mismatch"));
  EXPECT_THAT(reason, HasSubstr("sparc64/othercc-3/otherlib"));
  EXPECT_THAT(reason, HasSubstr(sdk_toolchain_fingerprint()));
}

TEST(LoadPlugin, ExceptionDuringRegistrationIsAFailureAndRegistersNothing) {
  const auto reason = failure_reason_of_case("throwing");
  EXPECT_THAT(reason, HasSubstr("registering stages failed"));
  EXPECT_THAT(reason, HasSubstr("calibration table missing"));
}

TEST(LoadPlugin, MissingFileNamesTheFile) {
  test::TempDir tmp;
  const auto reason = failure_reason(tmp.path() / "libfacet_missing.so");
  EXPECT_THAT(reason, HasSubstr("libfacet_missing.so"));
  EXPECT_THAT(reason, HasSubstr("No such file"));
}

TEST(LoadPlugin, FileThatIsNotALibraryNamesTheFile) {
  test::TempDir tmp;
  const auto file = tmp.path() / "libfacet_text.so";
  std::ofstream(file) << "this is not an ELF file, just some text long enough to be read\n";
  const auto reason = failure_reason(file);
  EXPECT_THAT(reason, HasSubstr("cannot load"));
  EXPECT_THAT(reason, HasSubstr("libfacet_text.so"));
}

// A plugin file cut short (an interrupted copy) made the dynamic loader die of SIGBUS, taking
// every command with it: the ELF headers are checked against the file's size first.
TEST(LoadPlugin, ATruncatedLibraryIsRefusedBeforeTheLoaderMapsIt) {
  const auto good = test::test_plugin_file("good");
  std::ifstream in(good, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_GT(bytes.size(), 16'384U);
  test::TempDir tmp;
  for (const std::size_t size :
       {std::size_t{4096}, bytes.size() / 4, bytes.size() / 2, bytes.size() - 1}) {
    const auto file = tmp.path() / ("libfacet_cut" + std::to_string(size) + ".so");
    std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(size));
    const auto reason = failure_reason(file);
    EXPECT_THAT(reason, HasSubstr(file.filename().string()));
    EXPECT_THAT(reason, HasSubstr("truncated or corrupt")) << size;
  }
  const auto tiny = tmp.path() / "libfacet_tiny.so";
  std::ofstream(tiny, std::ios::binary).write(bytes.data(), 40);
  EXPECT_THAT(failure_reason(tiny), HasSubstr("shorter than an ELF header"));
}

}  // namespace
}  // namespace facet
