// io.view without a display: one warning and the graph runs on, or an error when asked for; never
// a crash (Debian's highgui aborts the process when Qt cannot reach a display, so io.view must
// not touch it then).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <string>

#include "facet/error.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "view/display_probe.hpp"
#include "view/view_sink.hpp"

namespace facet::view {
namespace {

using ::testing::HasSubstr;
using Runner = facet::testing::StageRunner<ViewSink>;

// Each test is its own process under ctest, so the environment set here stays with the test.
void unset_display() {
  ::unsetenv("DISPLAY");
  ::unsetenv("WAYLAND_DISPLAY");
  ::unsetenv("QT_QPA_PLATFORM");
}

Packet depth_packet() {
  DepthImage image;
  image.depth = cv::Mat(4, 4, CV_16UC1, cv::Scalar(900));
  return Packet::make(image);
}

TEST(ViewHeadless, NoDisplayIsSaidPlainly) {
  unset_display();
  EXPECT_THAT(why_no_display().value_or(""), HasSubstr("DISPLAY and WAYLAND_DISPLAY are unset"));
  ::setenv("WAYLAND_DISPLAY", "wayland-0", 1);
  EXPECT_THAT(why_no_display().value_or(""), HasSubstr("QT_QPA_PLATFORM=wayland"));
}

TEST(ViewHeadless, AnX11DisplayThatDoesNotAnswerIsNoDisplay) {
  unset_display();
  ::setenv("DISPLAY", ":999", 1);  // no X server there
  EXPECT_THAT(why_no_display().value_or(""), HasSubstr("cannot connect to the X display ':999'"));
}

TEST(ViewHeadless, WarnsOnceAndLetsTheGraphRunOn) {
  unset_display();
  Runner runner({{"show", std::string("depth")}});
  runner.set_input("depth", depth_packet());
  runner.run();
  ASSERT_EQ(runner.warnings().size(), 1u);
  EXPECT_THAT(runner.warnings()[0], HasSubstr("io.view shows nothing"));
  EXPECT_THAT(runner.warnings()[0], HasSubstr("runs on"));
  for (int frame = 0; frame < 3; ++frame) {
    runner.run();
    EXPECT_TRUE(runner.warnings().empty()) << frame;
  }
}

TEST(ViewHeadless, RequireDisplayStopsTheRunNamingTheWindow) {
  unset_display();
  Runner runner({{"require_display", true}, {"title", std::string("tabletop")}});
  runner.set_input("depth", depth_packet());
  try {
    runner.run();
    ADD_FAILURE() << "opened without a display";
  } catch (const StageError& error) {
    EXPECT_THAT(error.what(), HasSubstr("cannot open window 'tabletop'"));
    EXPECT_THAT(error.what(), HasSubstr("DISPLAY"));
  }
}

}  // namespace
}  // namespace facet::view
