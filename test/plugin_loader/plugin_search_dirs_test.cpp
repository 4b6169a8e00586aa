// The order of plugin search directories and the origin reported for each.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "facet/framework/plugin_loader.hpp"
#include "test_support.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> origins(const std::vector<SearchDir>& dirs) {
  std::vector<std::string> result;
  for (const auto& dir : dirs)
    result.push_back(dir.origin);
  return result;
}

TEST(PluginSearchDirs, OrderIsCliThenEnvironmentThenGraphThenExecutableThenPrefix) {
  test::TempDir tmp;
  const auto dirs =
      plugin_search_dirs({tmp.path() / "cli1", tmp.path() / "cli2"},
                         (tmp.path() / "env1").string() + ":" + (tmp.path() / "env2").string(),
                         {tmp.path() / "graph"});
  ASSERT_GE(dirs.size(), 6u);
  EXPECT_EQ(dirs[0].dir, tmp.path() / "cli1");
  EXPECT_EQ(dirs[1].dir, tmp.path() / "cli2");
  EXPECT_EQ(dirs[2].dir, tmp.path() / "env1");
  EXPECT_EQ(dirs[3].dir, tmp.path() / "env2");
  EXPECT_EQ(dirs[4].dir, tmp.path() / "graph");
  const auto got = origins(dirs);
  EXPECT_THAT(std::vector<std::string>(got.begin(), got.begin() + 5),
              ::testing::ElementsAre("--plugin-path", "--plugin-path", "FACET_PLUGIN_PATH",
                                     "FACET_PLUGIN_PATH", "graph file"));
  // Then the directories found from the executable, then the configured install prefix, last.
  EXPECT_EQ(got[5], "executable");
  EXPECT_EQ(got.back(), "install prefix");
}

TEST(PluginSearchDirs, IncludesThePluginDirectoryOfThisBuildTree) {
  // The test program lives in <build>/bin, so "next to the executable" is this build's plugins.
  const auto dirs = plugin_search_dirs({}, "", {});
  const auto build_plugins = fs::weakly_canonical(FACET_PLUGIN_DIR);
  const bool found = std::any_of(dirs.begin(), dirs.end(), [&](const SearchDir& d) {
    return d.origin == "executable" && fs::weakly_canonical(d.dir) == build_plugins;
  });
  EXPECT_TRUE(found) << "expected " << build_plugins;
}

TEST(PluginSearchDirs, EmptyEnvironmentAndEmptyEntriesAddNothing) {
  const auto baseline = plugin_search_dirs({}, "", {});
  EXPECT_EQ(plugin_search_dirs({}, "::", {}).size(), baseline.size());
  EXPECT_EQ(baseline.front().origin, "executable");
}

TEST(PluginSearchDirs, SameDirectoryIsListedOnceAtItsFirstPosition) {
  test::TempDir tmp;
  const auto a = tmp.make_dir("a");
  const auto b = tmp.make_dir("b");
  // "a/../a" and "a/" name the same directory as "a".
  const auto dirs =
      plugin_search_dirs({a, b}, (a / ".." / "a").string() + ":" + b.string() + "/", {a});
  const auto count = std::count_if(dirs.begin(), dirs.end(), [&](const SearchDir& d) {
    return fs::weakly_canonical(d.dir) == fs::weakly_canonical(a);
  });
  EXPECT_EQ(count, 1);
  EXPECT_EQ(dirs[0].dir, a);
  EXPECT_EQ(dirs[1].dir, b);
  EXPECT_NE(dirs[2].origin, "FACET_PLUGIN_PATH");
}

TEST(PluginSearchDirs, MissingDirectoriesAreStillListed) {
  // `facet doctor` shows every directory searched, including the ones that do not exist.
  test::TempDir tmp;
  const auto dirs = plugin_search_dirs({tmp.path() / "missing"}, "", {});
  EXPECT_EQ(dirs.front().dir, tmp.path() / "missing");
}

}  // namespace
}  // namespace facet
