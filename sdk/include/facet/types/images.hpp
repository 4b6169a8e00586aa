#pragma once
// The image types stages exchange. Pixels are cv::Mat; every type carries its FrameHeader.
// Packets are immutable: a stage that changes an image makes a new one.
//
// Each type promises a format: a pixel type, one continuous block of pixels (so that a consumer
// may walk them with one pointer) and, when its camera is known, the camera's size. make() builds
// an image that keeps the promise, with the frame and camera of the image it was computed from,
// and throws std::invalid_argument saying what is wrong otherwise. format_error() says the same
// of an image built field by field. Every image a stage outputs or a host feeds is checked with
// it (ProcessContext::output_packet, facet::Pipeline), so consumers rely on the format and do not
// check it again.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>

#include "facet/packet.hpp"
#include "facet/types/frame.hpp"

namespace facet {

// Depth along the optical axis. Either CV_16UC1 in millimetres (0 = no measurement, as sensors
// deliver it) or CV_32FC1 in metres (0 or NaN = no measurement).
struct DepthImage : FrameHeader {
  cv::Mat depth;

  bool in_millimetres() const { return depth.type() == CV_16UC1; }

  static DepthImage make(const FrameHeader& frame, cv::Mat depth);
  // "" when the image keeps its format, else what is wrong ("depth is CV_8UC1, ...").
  std::string format_error() const;
};

// Organized 3D points in the camera frame, CV_32FC3 in metres; NaN = invalid.
struct PointImage : FrameHeader {
  cv::Mat points;

  static PointImage make(const FrameHeader& frame, cv::Mat points);
  std::string format_error() const;
};

// Unit surface normals, CV_32FC3, pointing towards the camera; NaN = no normal.
struct NormalImage : FrameHeader {
  cv::Mat normals;

  static NormalImage make(const FrameHeader& frame, cv::Mat normals);
  std::string format_error() const;
};

// Edge score (CV_32FC1, higher = smoother surface) and the binary decision (CV_8UC1, 255 = edge),
// of one size.
struct EdgeImage : FrameHeader {
  cv::Mat score;
  cv::Mat mask;

  static EdgeImage make(const FrameHeader& frame, cv::Mat score, cv::Mat mask);
  std::string format_error() const;
};

// Segment ids, CV_32SC1; 0 = background / unassigned, 1..count = segments. Every id lies in
// [0, count]; an id in between may be unused (a segment that was dropped keeps the others' ids).
struct LabelImage : FrameHeader {
  cv::Mat labels;
  std::int32_t count = 0;

  static LabelImage make(const FrameHeader& frame, cv::Mat labels, std::int32_t count);
  // The same, with `count` the largest id in `labels` (0 for an image without segments).
  static LabelImage counted(const FrameHeader& frame, cv::Mat labels);
  std::string format_error() const;
};

}  // namespace facet

FACET_TYPE_KEY(facet::DepthImage, "facet.DepthImage/1");
FACET_TYPE_KEY(facet::PointImage, "facet.PointImage/1");
FACET_TYPE_KEY(facet::NormalImage, "facet.NormalImage/1");
FACET_TYPE_KEY(facet::EdgeImage, "facet.EdgeImage/1");
FACET_TYPE_KEY(facet::LabelImage, "facet.LabelImage/1");
