#pragma once
// Which files in a search directory are plugins.

#include <filesystem>
#include <string>
#include <vector>

namespace facet::detail {

// libfacet_<name>.so (what facet_add_plugin builds) or <name>.facet.so.
bool is_plugin_file_name(const std::string& file_name);

// The plugin files directly inside `dir` (not recursive), sorted by file name so that loading
// order, and therefore which of two conflicting stages wins, does not depend on the file system.
// A missing or unreadable directory has no plugin files.
std::vector<std::filesystem::path> plugin_files_in(const std::filesystem::path& dir);

// "a:b::c" -> {"a", "b", "c"}; empty entries are dropped.
std::vector<std::filesystem::path> split_path_list(const std::string& value);

}  // namespace facet::detail
