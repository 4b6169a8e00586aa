#pragma once
// The image types stages exchange. Pixels are cv::Mat; every type carries its FrameHeader.
// Packets are immutable: a stage that changes an image makes a new one.

#include <cstdint>
#include <opencv2/core/mat.hpp>

#include "facet/packet.hpp"
#include "facet/types/frame.hpp"

namespace facet {

// Depth along the optical axis. Either CV_16UC1 in millimetres (0 = no measurement, as sensors
// deliver it) or CV_32FC1 in metres (0 or NaN = no measurement).
struct DepthImage : FrameHeader {
  cv::Mat depth;

  bool in_millimetres() const { return depth.type() == CV_16UC1; }
};

// Organized 3D points in the camera frame, CV_32FC3 in metres; NaN = invalid.
struct PointImage : FrameHeader {
  cv::Mat points;
};

// Unit surface normals, CV_32FC3, pointing towards the camera; NaN = no normal.
struct NormalImage : FrameHeader {
  cv::Mat normals;
};

// Edge score (CV_32FC1, higher = smoother surface) and the binary decision (CV_8UC1, 255 = edge).
struct EdgeImage : FrameHeader {
  cv::Mat score;
  cv::Mat mask;
};

// Segment ids, CV_32SC1; 0 = background / unassigned, 1..count = segments.
struct LabelImage : FrameHeader {
  cv::Mat labels;
  std::int32_t count = 0;
};

}  // namespace facet

FACET_TYPE_KEY(facet::DepthImage, "facet.DepthImage/1");
FACET_TYPE_KEY(facet::PointImage, "facet.PointImage/1");
FACET_TYPE_KEY(facet::NormalImage, "facet.NormalImage/1");
FACET_TYPE_KEY(facet::EdgeImage, "facet.EdgeImage/1");
FACET_TYPE_KEY(facet::LabelImage, "facet.LabelImage/1");
