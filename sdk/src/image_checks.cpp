#include "facet/image_checks.hpp"

#include <opencv2/core.hpp>
#include <string>

#include "facet/error.hpp"

namespace facet {
namespace {

std::string size_text(const cv::Mat& image) {
  return std::to_string(image.cols) + "x" + std::to_string(image.rows);
}

}  // namespace

void require_same_size(const cv::Mat& a, std::string_view port_a, const cv::Mat& b,
                       std::string_view port_b) {
  if (a.size() == b.size()) return;
  throw StageError("inputs '" + std::string(port_a) + "' (" + size_text(a) + ") and '" +
                   std::string(port_b) + "' (" + size_text(b) + ") differ in size");
}

}  // namespace facet
