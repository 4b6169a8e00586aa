// Which files count as plugins, directory listing order, and FACET_PLUGIN_PATH parsing.

#include "plugin_files.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "test_support.hpp"

namespace facet::detail {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& file) {
  std::ofstream(file) << "x";
}

TEST(PluginFileName, MatchesOnlyPluginNames) {
  EXPECT_TRUE(is_plugin_file_name("libfacet_filters.so"));
  EXPECT_TRUE(is_plugin_file_name("my_stages.facet.so"));
  EXPECT_FALSE(is_plugin_file_name("libfacet_.so"));
  EXPECT_FALSE(is_plugin_file_name("libfacet_filters.so.1"));
  EXPECT_FALSE(is_plugin_file_name("libfilters.so"));
  EXPECT_FALSE(is_plugin_file_name("libfacet_filters.a"));
  EXPECT_FALSE(is_plugin_file_name(".facet.so"));
}

TEST(PluginFilesIn, ListsPluginFilesSortedAndNotRecursively) {
  test::TempDir tmp;
  touch(tmp.path() / "libfacet_zeta.so");
  touch(tmp.path() / "libfacet_alpha.so");
  touch(tmp.path() / "libother.so");
  touch(tmp.path() / "README.md");
  fs::create_directories(tmp.path() / "libfacet_dir.so");  // a directory, not a plugin
  touch(tmp.make_dir("nested") / "libfacet_nested.so");

  const auto files = plugin_files_in(tmp.path());
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].filename(), "libfacet_alpha.so");
  EXPECT_EQ(files[1].filename(), "libfacet_zeta.so");
}

TEST(PluginFilesIn, FollowsSymlinksToPluginFiles) {
  test::TempDir tmp;
  touch(tmp.path() / "real.so");
  fs::create_symlink(tmp.path() / "real.so", tmp.path() / "libfacet_linked.so");
  fs::create_symlink(tmp.path() / "gone.so", tmp.path() / "libfacet_dangling.so");
  const auto files = plugin_files_in(tmp.path());
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].filename(), "libfacet_linked.so");
}

TEST(PluginFilesIn, MissingDirectoryAndPlainFileHaveNoPlugins) {
  test::TempDir tmp;
  EXPECT_TRUE(plugin_files_in(tmp.path() / "does-not-exist").empty());
  touch(tmp.path() / "libfacet_file.so");
  EXPECT_TRUE(plugin_files_in(tmp.path() / "libfacet_file.so").empty());
}

TEST(SplitPathList, SplitsOnColonsAndDropsEmptyEntries) {
  EXPECT_TRUE(split_path_list("").empty());
  EXPECT_TRUE(split_path_list(":::").empty());
  EXPECT_EQ(split_path_list("/a"), (std::vector<fs::path>{"/a"}));
  EXPECT_EQ(split_path_list(":/a::rel/b:"), (std::vector<fs::path>{"/a", "rel/b"}));
  EXPECT_EQ(split_path_list("/a b:/c"), (std::vector<fs::path>{"/a b", "/c"}));
}

}  // namespace
}  // namespace facet::detail
