#include "facet/types/images.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <utility>

namespace facet {
namespace {

std::string size_text(int cols, int rows) {
  return std::to_string(cols) + "x" + std::to_string(rows);
}

// What is wrong with one plane of an image (`what` names it: "depth", "mask"), or "".
// `type_text` lists the accepted types for the message.
std::string plane_error(const cv::Mat& image, const char* what, bool type_ok, const char* type_text,
                        const CameraIntrinsics& camera) {
  if (image.empty()) return std::string(what) + " is empty";
  if (!type_ok) {
    return std::string(what) + " is " + cv::typeToString(image.type()) + ", must be " + type_text;
  }
  if (image.dims != 2) return std::string(what) + " has " + std::to_string(image.dims) + " dims";
  if (!image.isContinuous()) {
    return std::string(what) + " is not continuous (a view into a larger image); clone() it";
  }
  if (camera.valid() && (image.cols != camera.width || image.rows != camera.height)) {
    return std::string(what) + " is " + size_text(image.cols, image.rows) +
           ", its camera's intrinsics are " + size_text(camera.width, camera.height);
  }
  return {};
}

// The largest id of `ids`, read as unsigned: a negative id reads as one above 2^31, so a single
// comparison with the count finds ids that are negative and ids that are too large. Every label
// image a stage outputs is scanned once or twice (make() and the output port), so this one pass is
// vectorised: 25 us for 640x480 ids with AVX2 where cv::minMaxIdx takes 160 us.
__attribute__((target_clones("avx2", "default"))) std::uint32_t largest_unsigned(
    const std::int32_t* ids, std::size_t count) {
  std::uint32_t largest = 0;
  for (std::size_t i = 0; i < count; ++i) {
    largest = std::max(largest, static_cast<std::uint32_t>(ids[i]));
  }
  return largest;
}

// The label image's plane: everything but its ids' range.
std::string label_plane_error(const LabelImage& image) {
  return plane_error(image.labels, "labels", image.labels.type() == CV_32SC1, "CV_32SC1",
                     image.camera);
}

template <class Image>
Image checked(Image image) {
  if (std::string error = image.format_error(); !error.empty()) {
    throw std::invalid_argument(std::move(error));
  }
  return image;
}

}  // namespace

DepthImage DepthImage::make(const FrameHeader& frame, cv::Mat depth) {
  return checked(DepthImage{frame, std::move(depth)});
}

std::string DepthImage::format_error() const {
  const int type = depth.type();
  return plane_error(depth, "depth", type == CV_16UC1 || type == CV_32FC1,
                     "CV_16UC1 (mm) or CV_32FC1 (m)", camera);
}

PointImage PointImage::make(const FrameHeader& frame, cv::Mat points) {
  return checked(PointImage{frame, std::move(points)});
}

std::string PointImage::format_error() const {
  return plane_error(points, "points", points.type() == CV_32FC3, "CV_32FC3", camera);
}

NormalImage NormalImage::make(const FrameHeader& frame, cv::Mat normals) {
  return checked(NormalImage{frame, std::move(normals)});
}

std::string NormalImage::format_error() const {
  return plane_error(normals, "normals", normals.type() == CV_32FC3, "CV_32FC3", camera);
}

EdgeImage EdgeImage::make(const FrameHeader& frame, cv::Mat score, cv::Mat mask) {
  return checked(EdgeImage{frame, std::move(score), std::move(mask)});
}

std::string EdgeImage::format_error() const {
  if (std::string error = plane_error(score, "score", score.type() == CV_32FC1, "CV_32FC1", camera);
      !error.empty()) {
    return error;
  }
  if (std::string error = plane_error(mask, "mask", mask.type() == CV_8UC1, "CV_8UC1", camera);
      !error.empty()) {
    return error;
  }
  if (score.size() != mask.size()) {
    return "score (" + size_text(score.cols, score.rows) + ") and mask (" +
           size_text(mask.cols, mask.rows) + ") differ in size";
  }
  return {};
}

LabelImage LabelImage::make(const FrameHeader& frame, cv::Mat labels, std::int32_t count) {
  return checked(LabelImage{frame, std::move(labels), count});
}

LabelImage LabelImage::counted(const FrameHeader& frame, cv::Mat labels) {
  LabelImage image{frame, std::move(labels), 0};
  if (std::string error = label_plane_error(image); !error.empty()) {
    throw std::invalid_argument(std::move(error));
  }
  const std::uint32_t largest =
      largest_unsigned(image.labels.ptr<std::int32_t>(), image.labels.total());
  // Above INT32_MAX the image holds a negative id: the full check refuses it, naming the id.
  if (largest > static_cast<std::uint32_t>(INT32_MAX)) return checked(std::move(image));
  // Every id lies in [0, largest] by construction: no second scan.
  image.count = static_cast<std::int32_t>(largest);
  return image;
}

std::string LabelImage::format_error() const {
  if (std::string error = label_plane_error(*this); !error.empty()) return error;
  if (count < 0) return "count is " + std::to_string(count) + ", must be 0 or more";
  if (largest_unsigned(labels.ptr<std::int32_t>(), labels.total()) <=
      static_cast<std::uint32_t>(count)) {
    return {};
  }
  double smallest = 0.0;  // an id out of range: find which, for the message
  double largest = 0.0;
  cv::minMaxIdx(labels, &smallest, &largest);
  if (smallest < 0.0) {
    return "labels hold the id " + std::to_string(static_cast<long long>(smallest)) +
           "; ids are 0 (background) or 1..count";
  }
  if (largest > count) {
    return "labels hold the id " + std::to_string(static_cast<long long>(largest)) +
           ", above their count " + std::to_string(count);
  }
  return {};
}

}  // namespace facet
