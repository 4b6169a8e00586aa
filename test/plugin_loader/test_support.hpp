#pragma once
// Helpers shared by the plugin loader tests.

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

#include "facet/framework/registry.hpp"
#include "temp_dir.hpp"

namespace facet::test {

// The directory and file of a test plugin built by test/plugin_loader/CMakeLists.txt.
inline std::filesystem::path test_plugin_dir(const std::string& test_case) {
  return std::filesystem::path(FACET_TEST_PLUGINS_DIR) / test_case;
}
inline std::filesystem::path test_plugin_file(const std::string& test_case) {
  return test_plugin_dir(test_case) / ("libfacet_" + test_case + ".so");
}

// "file: reason" lines of every failure, for assertion messages.
inline std::string describe_failures(const Registry& registry) {
  std::string text;
  for (const auto& failure : registry.failures()) {
    text += failure.file.string() + ": " + failure.reason + "\n";
  }
  return text;
}

}  // namespace facet::test
