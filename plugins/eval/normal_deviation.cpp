#include "eval/normal_deviation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

#include "facet/error.hpp"

namespace facet::eval {
namespace {

bool valid(const cv::Vec3f& n) {
  return std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]) && n.dot(n) > 0.0F;
}

}  // namespace

std::vector<double> angular_deviations_deg(const cv::Mat& normals_before,
                                           const cv::Mat& normals_after, const cv::Mat& region) {
  CV_Assert(normals_before.type() == CV_32FC3 && normals_after.type() == CV_32FC3);
  CV_Assert(normals_before.size() == normals_after.size());
  CV_Assert(region.empty() || (region.type() == CV_8UC1 && region.size() == normals_after.size()));
  std::vector<double> degrees;
  for (int y = 0; y < normals_after.rows; ++y) {
    const auto* before = normals_before.ptr<cv::Vec3f>(y);
    const auto* after = normals_after.ptr<cv::Vec3f>(y);
    const auto* inside = region.empty() ? nullptr : region.ptr<std::uint8_t>(y);
    for (int x = 0; x < normals_after.cols; ++x) {
      if (inside != nullptr && inside[x] == 0) continue;
      if (!valid(before[x]) || !valid(after[x])) continue;
      const cv::Vec3d a(before[x]);
      const cv::Vec3d b(after[x]);
      // atan2 of |a x b| and a.b stays accurate for the small angles that matter here, where
      // acos of a dot product near 1 loses its digits.
      const double angle = std::atan2(cv::norm(a.cross(b)), a.dot(b));
      degrees.push_back(angle * 180.0 / std::numbers::pi);
    }
  }
  return degrees;
}

}  // namespace facet::eval

std::variant<facet::eval::PixelRect, std::string> facet::ParamTraits<facet::eval::PixelRect>::parse(
    std::string_view text) {
  if (text.find_first_not_of(' ') == std::string_view::npos) return eval::PixelRect{};
  int values[4] = {0, 0, 0, 0};
  const char* cursor = text.data();
  const char* end = text.data() + text.size();
  std::string refused = "'";
  refused.append(text);
  refused.append(
      "' is no rectangle (expected \"x, y, width, height\" in pixels, width and height "
      "positive)");
  for (int i = 0; i < 4; ++i) {
    while (cursor < end && *cursor == ' ')
      ++cursor;
    const auto [ptr, error] = std::from_chars(cursor, end, values[i]);
    if (error != std::errc()) return refused;
    cursor = ptr;
    while (cursor < end && *cursor == ' ')
      ++cursor;
    if (i < 3) {
      if (cursor == end || *cursor != ',') return refused;
      ++cursor;
    }
  }
  if (cursor != end || values[0] < 0 || values[1] < 0 || values[2] <= 0 || values[3] <= 0) {
    return refused;
  }
  return eval::PixelRect{cv::Rect(values[0], values[1], values[2], values[3])};
}

std::string facet::ParamTraits<facet::eval::PixelRect>::format(const eval::PixelRect& value) {
  if (value.rect.empty()) return "";
  const cv::Rect& r = value.rect;
  return std::to_string(r.x) + ", " + std::to_string(r.y) + ", " + std::to_string(r.width) + ", " +
         std::to_string(r.height);
}
