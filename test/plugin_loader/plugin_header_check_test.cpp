// The header checks on in-memory headers: every field that can refuse a plugin, with both sides.

#include "plugin_header_check.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "facet/version.hpp"

namespace facet::detail {
namespace {

using ::testing::HasSubstr;

void register_nothing(void*) {}

facet_plugin_header valid_header() {
  return {FACET_PLUGIN_MAGIC,
          FACET_PLUGIN_ABI_VERSION,
          static_cast<uint32_t>(sizeof(facet_plugin_header)),
          FACET_SDK_VERSION_MAJOR,
          FACET_SDK_VERSION_MINOR,
          FACET_SDK_VERSION_PATCH,
          sdk_toolchain_fingerprint(),
          "example",
          "1.0",
          &register_nothing};
}

TEST(PluginHeaderCheck, AcceptsTheHeaderFacetPluginWrites) {
  EXPECT_EQ(check_plugin_header(valid_header()), std::nullopt);
}

TEST(PluginHeaderCheck, AcceptsAnotherPatchVersionAndALargerHeader) {
  auto header = valid_header();
  header.sdk_version_patch += 7;
  header.header_size += 16;  // a newer plugin that appended fields
  EXPECT_EQ(check_plugin_header(header), std::nullopt);
}

TEST(PluginHeaderCheck, RefusesWrongMagicPrintingBothValues) {
  auto header = valid_header();
  header.magic = 0x12345678u;
  const auto reason = check_plugin_header(header).value_or("");
  EXPECT_THAT(reason, HasSubstr("0x12345678"));
  EXPECT_THAT(reason, HasSubstr("0x54454346"));
}

TEST(PluginHeaderCheck, RefusesWrongAbiVersionPrintingBothValues) {
  auto header = valid_header();
  header.abi_version = 999;
  EXPECT_EQ(check_plugin_header(header).value_or(""),
            "ABI version mismatch: plugin has 999, host expects " +
                std::to_string(FACET_PLUGIN_ABI_VERSION));
}

TEST(PluginHeaderCheck, AbiVersionIsCheckedBeforeTheFieldsItDescribes) {
  auto header = valid_header();
  header.abi_version = FACET_PLUGIN_ABI_VERSION + 1;
  header.toolchain = nullptr;  // must not be read
  EXPECT_THAT(check_plugin_header(header).value_or(""), HasSubstr("ABI version mismatch"));
}

TEST(PluginHeaderCheck, RefusesATruncatedHeader) {
  auto header = valid_header();
  header.header_size = 16;
  const auto reason = check_plugin_header(header).value_or("");
  EXPECT_THAT(reason, HasSubstr("plugin has 16 bytes"));
  EXPECT_THAT(reason, HasSubstr(std::to_string(sizeof(facet_plugin_header))));
}

TEST(PluginHeaderCheck, RefusesAnotherSdkMinorOrMajorVersion) {
  auto header = valid_header();
  header.sdk_version_minor += 1;
  const auto minor = check_plugin_header(header).value_or("");
  EXPECT_THAT(minor, HasSubstr("SDK version mismatch"));
  EXPECT_THAT(minor, HasSubstr("SDK " + plugin_sdk_version(header)));
  EXPECT_THAT(minor, HasSubstr(std::string("host has SDK ") + FACET_SDK_VERSION_STRING));

  header = valid_header();
  header.sdk_version_major += 1;
  EXPECT_THAT(check_plugin_header(header).value_or(""), HasSubstr("SDK version mismatch"));
}

TEST(PluginHeaderCheck, RefusesAnotherToolchainPrintingBoth) {
  auto header = valid_header();
  header.toolchain = "sparc64/othercc-3/otherlib";
  const auto reason = check_plugin_header(header).value_or("");
  EXPECT_THAT(reason, HasSubstr("toolchain mismatch"));
  EXPECT_THAT(reason, HasSubstr("'sparc64/othercc-3/otherlib'"));
  EXPECT_THAT(reason, HasSubstr(std::string("'") + sdk_toolchain_fingerprint() + "'"));
}

TEST(PluginHeaderCheck, RefusesMissingPointers) {
  auto header = valid_header();
  header.toolchain = nullptr;
  EXPECT_THAT(check_plugin_header(header).value_or(""), HasSubstr("(none)"));
  header = valid_header();
  header.plugin_name = "";
  EXPECT_THAT(check_plugin_header(header).value_or(""), HasSubstr("no plugin name"));
  header = valid_header();
  header.register_stages = nullptr;
  EXPECT_THAT(check_plugin_header(header).value_or(""), HasSubstr("no register_stages"));
}

}  // namespace
}  // namespace facet::detail
