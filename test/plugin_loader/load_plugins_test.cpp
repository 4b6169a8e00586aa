// load_plugins(): directories in order, shadowing by file name, missing directories, conflicts.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "facet/framework/plugin_loader.hpp"
#include "test_support.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

SearchDir dir(fs::path path) {
  return {std::move(path), "test"};
}

TEST(LoadPlugins, EarlierDirectoryShadowsTheSameFileNameLater) {
  test::TempDir tmp;
  const auto first = tmp.make_dir("first");
  const auto second = tmp.make_dir("second");
  fs::copy_file(test::test_plugin_file("good"), first / "libfacet_good.so");
  // A different plugin under the same file name: it would conflict if it were loaded.
  fs::copy_file(test::test_plugin_file("duplicate"), second / "libfacet_good.so");

  Registry registry;
  load_plugins({dir(first), dir(second)}, registry);
  EXPECT_TRUE(registry.failures().empty()) << test::describe_failures(registry);
  ASSERT_EQ(registry.plugins().size(), 1u);
  EXPECT_EQ(registry.plugins()[0]->file, first / "libfacet_good.so");
  EXPECT_EQ(registry.plugins()[0]->name, "good");
}

TEST(LoadPlugins, OtherFileNamesInLaterDirectoriesAreLoaded) {
  test::TempDir tmp;
  const auto first = tmp.make_dir("first");
  const auto second = tmp.make_dir("second");
  fs::copy_file(test::test_plugin_file("good"), first / "libfacet_good.so");
  fs::copy_file(test::test_plugin_file("no_entry"), second / "libfacet_no_entry.so");

  Registry registry;
  load_plugins({dir(first), dir(second)}, registry);
  EXPECT_EQ(registry.plugins().size(), 1u);
  ASSERT_EQ(registry.failures().size(), 1u);
  EXPECT_EQ(registry.failures()[0].file, second / "libfacet_no_entry.so");
}

TEST(LoadPlugins, MissingDirectoriesAreSkipped) {
  test::TempDir tmp;
  Registry registry;
  load_plugins({dir(tmp.path() / "missing"), dir(test::test_plugin_dir("good")),
                dir(tmp.path() / "also-missing")},
               registry);
  EXPECT_TRUE(registry.failures().empty()) << test::describe_failures(registry);
  EXPECT_NE(registry.find("test.constant"), nullptr);
}

TEST(LoadPlugins, TwoPluginsWithTheSameStageNameNameBothFiles) {
  Registry registry;
  load_plugins({dir(test::test_plugin_dir("good")), dir(test::test_plugin_dir("duplicate"))},
               registry);
  ASSERT_EQ(registry.failures().size(), 1u) << test::describe_failures(registry);
  const auto& failure = registry.failures()[0];
  EXPECT_EQ(failure.file, test::test_plugin_file("duplicate"));
  EXPECT_THAT(failure.reason, HasSubstr("test.constant"));
  EXPECT_THAT(failure.reason, HasSubstr(test::test_plugin_file("good").string()));
  EXPECT_THAT(failure.reason, HasSubstr(test::test_plugin_file("duplicate").string()));
  // The first plugin keeps the stage.
  ASSERT_NE(registry.find("test.constant"), nullptr);
  EXPECT_EQ(registry.find("test.constant")->plugin->name, "good");
}

TEST(LoadPlugins, FilesInOneDirectoryLoadInNameOrder) {
  // Whichever file sorts first owns a contested stage, whatever order the file system lists.
  test::TempDir tmp;
  fs::copy_file(test::test_plugin_file("good"), tmp.path() / "libfacet_b.so");
  fs::copy_file(test::test_plugin_file("duplicate"), tmp.path() / "libfacet_a.so");

  Registry registry;
  load_plugins({dir(tmp.path())}, registry);
  ASSERT_NE(registry.find("test.constant"), nullptr);
  EXPECT_EQ(registry.find("test.constant")->plugin->name, "duplicate");
  ASSERT_EQ(registry.failures().size(), 1u);
  EXPECT_EQ(registry.failures()[0].file, tmp.path() / "libfacet_b.so");
}

TEST(LoadPlugins, EveryBrokenPluginIsRecordedAndTheGoodOneStillLoads) {
  const std::vector<std::string> broken = {"bad_magic",       "no_entry",         "short_header",
                                           "throwing",        "undefined_symbol", "wrong_abi",
                                           "wrong_sdk_minor", "wrong_toolchain"};
  std::vector<SearchDir> dirs;
  for (const auto& test_case : broken)
    dirs.push_back(dir(test::test_plugin_dir(test_case)));
  dirs.push_back(dir(test::test_plugin_dir("good")));

  Registry registry;
  load_plugins(dirs, registry);
  EXPECT_EQ(registry.stage_names(), std::vector<std::string>{"test.constant"});
  ASSERT_EQ(registry.failures().size(), broken.size()) << test::describe_failures(registry);
  for (std::size_t i = 0; i < broken.size(); ++i) {
    EXPECT_EQ(registry.failures()[i].file, test::test_plugin_file(broken[i]));
    EXPECT_FALSE(registry.failures()[i].reason.empty());
  }
}

}  // namespace
}  // namespace facet
