#include "plugin_files.hpp"

#include <algorithm>
#include <string_view>
#include <system_error>

namespace facet::detail {

namespace fs = std::filesystem;

bool is_plugin_file_name(const std::string& file_name) {
  const std::string_view name = file_name;
  const auto stem_between = [&](std::string_view prefix, std::string_view suffix) {
    return name.size() > prefix.size() + suffix.size() && name.starts_with(prefix) &&
           name.ends_with(suffix);
  };
  return stem_between("libfacet_", ".so") || stem_between("", ".facet.so");
}

std::vector<fs::path> plugin_files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) return files;
  for (const fs::directory_iterator end; it != end; it.increment(ec)) {
    if (ec) break;
    std::error_code type_ec;
    // is_regular_file follows symlinks, so a link to a plugin elsewhere counts.
    if (!it->is_regular_file(type_ec) || type_ec) continue;
    if (is_plugin_file_name(it->path().filename().string())) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end(),
            [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
  return files;
}

std::vector<fs::path> split_path_list(const std::string& value) {
  std::vector<fs::path> paths;
  std::string_view rest = value;
  while (!rest.empty()) {
    const auto colon = rest.find(':');
    const auto entry = rest.substr(0, colon);
    if (!entry.empty()) paths.emplace_back(entry);
    if (colon == std::string_view::npos) break;
    rest.remove_prefix(colon + 1);
  }
  return paths;
}

}  // namespace facet::detail
