#include "facet/image_checks.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <opencv2/core.hpp>

#include "facet/error.hpp"

namespace {

std::string message_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const facet::StageError& e) {
    return e.what();
  }
  return "";
}

TEST(ImageChecks, SizeMismatchNamesBothPortsAndSizes) {
  const cv::Mat a(480, 640, CV_32SC1);
  const cv::Mat b(240, 320, CV_32FC3);
  EXPECT_NO_THROW(facet::require_same_size(a, "patches", a, "labels"));
  EXPECT_EQ(message_of([&] { facet::require_same_size(a, "patches", b, "points"); }),
            "inputs 'patches' (640x480) and 'points' (320x240) differ in size");
}

}  // namespace
