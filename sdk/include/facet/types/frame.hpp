#pragma once
// What every image-like packet carries besides its pixels: which frame it belongs to and the
// camera that saw it.

#include <concepts>
#include <cstdint>
#include <string>

namespace facet {

// Pinhole intrinsics of the depth image, in pixels. Back-projection of pixel (u, v) at depth Z:
// X = (u - cx) * Z / fx, Y = (v - cy) * Z / fy.
struct CameraIntrinsics {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  int width = 0;
  int height = 0;

  bool valid() const { return fx > 0.0 && fy > 0.0 && width > 0 && height > 0; }
  bool operator==(const CameraIntrinsics&) const = default;
};

struct FrameInfo {
  std::int64_t index = 0;         // 0-based position in the stream
  std::int64_t timestamp_ns = 0;  // capture time, or index * nominal period for recordings
  std::string stem;               // name of the source file without extension, e.g. "learn0"
  // Frames the stream will hold when the source knows it in advance (a recording played once);
  // 0 when it does not (a camera, a topic, a looping recording). For progress displays.
  std::int64_t stream_frames = 0;
  // The camera's coordinate frame as a ROS message header names it, e.g.
  // "camera_depth_optical_frame"; empty when the source does not say (files, OpenNI2). Carried
  // so that results published on a ROS network keep the frame of the camera they came from.
  std::string camera_frame_id;
};

// Common header of every image-like type.
struct FrameHeader {
  FrameInfo frame;
  CameraIntrinsics camera;
};

// An empty T (a type derived from FrameHeader) that belongs to the frame of `input`: it carries
// its frame and camera, as every output computed from `input` must.
//   auto list = of_frame<ObjectList>(labels);
// The image types have checked factories for the same (DepthImage::make, facet/types/images.hpp).
template <std::derived_from<FrameHeader> T>
T of_frame(const FrameHeader& input) {
  T output{};
  static_cast<FrameHeader&>(output) = input;
  return output;
}

}  // namespace facet
