// graphs/live.yaml without a camera and without a display: the bundled frames recorded as an .oni
// file (graphs/record_oni.yaml) play through io.openni2 into the whole tabletop chain, and
// io.view says once that it shows nothing while every frame runs.

#include <gtest/gtest.h>

#include <string>

#include "cli_runner.hpp"

namespace facet::test {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

TEST(LiveGraph, PlaysARecordingOfTheBundledFramesHeadless) {
  TempDir out("facet-live");
  const auto recording = out.path() / "mosd.oni";
  const auto recorded =
      run_cli("run " + shell_quote((source_dir() / "graphs/record_oni.yaml").string()) +
              " --param output=" + shell_quote(recording.string()));
  ASSERT_EQ(recorded.exit_code, 0) << recorded.out;

  const auto json = out.path() / "stats.json";
  const auto result = run_cli("run " + shell_quote((source_dir() / "graphs/live.yaml").string()) +
                                  " --param uri=" + shell_quote(recording.string()) + " --json " +
                                  shell_quote(json.string()),
                              "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(count(result.out, "io.view shows nothing: no display"), 1u) << result.out;
  // Every bundled frame went through, and the stream ended at the end of the file.
  const std::string stats = read_file(json);
  EXPECT_NE(stats.find("\"frames\": 6"), std::string::npos) << stats;
  EXPECT_NE(stats.find("dropped_frames"), std::string::npos) << stats;

  // The same run with require_display stops, saying why.
  const auto strict = run_cli("run " + shell_quote((source_dir() / "graphs/live.yaml").string()) +
                                  " --param uri=" + shell_quote(recording.string()) +
                                  " --set view.require_display=true",
                              "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM");
  EXPECT_EQ(strict.exit_code, 1) << strict.out;
  EXPECT_NE(strict.out.find("cannot open window 'facet live'"), std::string::npos) << strict.out;
}

}  // namespace
}  // namespace facet::test
