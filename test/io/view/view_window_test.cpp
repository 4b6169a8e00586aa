// io.view with a display (run under xvfb-run): the window opens, frames are shown in it, and it
// is gone after the stage closes.

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <opencv2/highgui.hpp>
#include <string>

#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"
#include "view/display_probe.hpp"
#include "view/view_sink.hpp"

namespace facet::view {
namespace {

using Runner = facet::testing::StageRunner<ViewSink>;

TEST(ViewWindow, OpensShowsFramesAndClosesUnderAnXServer) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run this program under xvfb-run";
  ASSERT_EQ(why_no_display(), std::nullopt);

  const std::string title = "facet view test";
  {
    Runner runner({{"show", std::string("labels")}, {"title", title}, {"scale", 2.0}});
    DepthImage depth;
    depth.depth = cv::Mat(40, 60, CV_16UC1, cv::Scalar(1000));
    LabelImage labels;
    labels.labels = cv::Mat::zeros(40, 60, CV_32SC1);
    labels.labels(cv::Rect(10, 10, 20, 20)).setTo(1);
    labels.count = 1;
    runner.set_input("depth", Packet::make(depth));
    runner.set_input("labels", Packet::make(labels));
    for (int frame = 0; frame < 3; ++frame) {
      runner.run();
      EXPECT_TRUE(runner.warnings().empty()) << runner.warnings().front();
    }
    // The window exists, large enough for the picture (60x40 at scale 2; Qt adds its margins).
    EXPECT_EQ(cv::getWindowProperty(title, cv::WND_PROP_AUTOSIZE), 1.0);
    const cv::Rect frame = cv::getWindowImageRect(title);
    EXPECT_GE(frame.width, 120);
    EXPECT_GE(frame.height, 80);
    EXPECT_LT(frame.width, 240);
  }
  // Closed with the stage: OpenCV no longer knows the window (it says so by an exception once
  // its last window is gone, by -1 while others are open).
  cv::waitKey(1);
  double property = -1.0;
  try {
    property = cv::getWindowProperty(title, cv::WND_PROP_AUTOSIZE);
  } catch (const cv::Exception&) {
    property = -1.0;
  }
  EXPECT_LT(property, 0.0);
}

}  // namespace
}  // namespace facet::view
