#pragma once
// Helpers shared by the plugin loader tests.

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

#include "facet/framework/registry.hpp"

namespace facet::test {

// A fresh directory under the system temp dir, removed with everything in it at scope exit.
class TempDir {
 public:
  TempDir() {
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            ("facet-loader-test-" + std::to_string(random()) + std::to_string(random()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path make_dir(const std::string& name) const {
    std::filesystem::create_directories(path_ / name);
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};

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
