#pragma once
// A fresh, empty folder under the system temp directory for one test, removed with everything in
// it when the test is done. Names are unique across processes (ctest runs tests in parallel).

#include <atomic>
#include <filesystem>
#include <random>
#include <string>
#include <system_error>

namespace facet::test {

class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "facet-test") {
    static std::atomic<unsigned> counter{0};
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            (prefix + "-" + std::to_string(random()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Creates and returns the sub-folder `name`.
  std::filesystem::path make_dir(const std::string& name) const {
    std::filesystem::create_directories(path_ / name);
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace facet::test
