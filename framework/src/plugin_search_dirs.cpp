// plugin_search_dirs(): where plugins are looked for, in order (see plugin_loader.hpp).

#include <boost/dll/runtime_symbol_info.hpp>
#include <optional>
#include <set>
#include <system_error>

#include "facet/framework/plugin_loader.hpp"
#include "plugin_files.hpp"

namespace facet {

namespace fs = std::filesystem;

namespace {

// The directory of the running program, or nothing when the system cannot tell.
std::optional<fs::path> executable_dir() {
  boost::dll::fs::error_code ec;
  const auto location = boost::dll::program_location(ec);
  if (!ec && !location.empty()) return fs::path(location.parent_path().native());
  std::error_code proc_ec;
  const auto proc = fs::read_symlink("/proc/self/exe", proc_ec);
  if (!proc_ec && !proc.empty()) return proc.parent_path();
  return std::nullopt;
}

// Collects directories, dropping any that names the same place as an earlier one: a directory
// searched twice could only ever be shadowed by itself.
class SearchDirList {
 public:
  void add(fs::path dir, std::string origin) {
    std::error_code ec;
    auto key = fs::weakly_canonical(dir, ec);
    if (ec) key = fs::absolute(dir, ec).lexically_normal();
    if (!seen_.insert(key).second) return;
    dirs_.push_back({std::move(dir), std::move(origin)});
  }
  std::vector<SearchDir> take() { return std::move(dirs_); }

 private:
  std::set<fs::path> seen_;
  std::vector<SearchDir> dirs_;
};

}  // namespace

std::vector<SearchDir> plugin_search_dirs(const std::vector<fs::path>& cli_paths,
                                          const std::string& environment_value,
                                          const std::vector<fs::path>& graph_paths) {
  SearchDirList dirs;
  for (const auto& dir : cli_paths)
    dirs.add(dir, "--plugin-path");
  for (auto& dir : detail::split_path_list(environment_value)) {
    dirs.add(std::move(dir), "FACET_PLUGIN_PATH");
  }
  for (const auto& dir : graph_paths)
    dirs.add(dir, "graph file");
  // Next to the executable: the build tree and a relocated install tree share this layout.
  if (const auto exe_dir = executable_dir()) {
    for (const char* relative : {FACET_EXE_TO_BUILD_PLUGINS, FACET_EXE_TO_INSTALLED_PLUGINS}) {
      dirs.add((*exe_dir / relative).lexically_normal(), "executable");
    }
  }
  dirs.add(FACET_INSTALL_PLUGIN_DIR, "install prefix");
  return dirs.take();
}

}  // namespace facet
