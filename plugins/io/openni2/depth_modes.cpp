#include "openni2/depth_modes.hpp"

#include <cmath>

#include "facet/error.hpp"

namespace facet::openni2 {
namespace {

bool same_size_and_rate(const DepthMode& a, const DepthMode& b) {
  return a.width_px == b.width_px && a.height_px == b.height_px && a.fps == b.fps;
}

bool matches(const DepthMode& mode, const ModeRequest& request) {
  return (request.width_px == 0 || mode.width_px == request.width_px) &&
         (request.height_px == 0 || mode.height_px == request.height_px) &&
         (request.fps == 0 || mode.fps == request.fps);
}

std::string describe(const ModeRequest& request) {
  const auto field = [](int value, const char* unit) {
    return value == 0 ? std::string("any ") + unit : std::to_string(value) + " " + unit;
  };
  return field(request.width_px, "width") + ", " + field(request.height_px, "height") + ", " +
         field(request.fps, "fps");
}

std::string list_modes(const std::vector<DepthMode>& modes) {
  if (modes.empty()) return "(the device lists no depth modes)";
  std::string text;
  for (const auto& mode : modes) {
    if (!text.empty()) text += "; ";
    text += describe(mode);
  }
  return text;
}

}  // namespace

std::string describe(const DepthMode& mode) {
  return std::to_string(mode.width_px) + "x" + std::to_string(mode.height_px) + " @ " +
         std::to_string(mode.fps) + " fps, " + mode.pixel_format;
}

DepthMode choose_depth_mode(const std::vector<DepthMode>& supported, const DepthMode& current,
                            const ModeRequest& request, const std::string& uri) {
  if (request.empty()) {
    if (current.millimetres) return current;
    for (const auto& mode : supported) {
      if (mode.millimetres && same_size_and_rate(mode, current)) return mode;
    }
    for (const auto& mode : supported) {
      if (mode.millimetres) return mode;
    }
    throw StageError("'" + uri + "' offers no depth mode in millimetres (current mode " +
                     describe(current) + "); supported modes: " + list_modes(supported));
  }
  for (const auto& mode : supported) {
    if (mode.millimetres && matches(mode, request)) return mode;
  }
  throw StageError(
      "'" + uri + "' has no depth mode in millimetres with " + describe(request) +
      " (params width, height, fps; 0 = any); supported modes: " + list_modes(supported));
}

CameraIntrinsics intrinsics_from_fov(int width_px, int height_px, double hfov_rad,
                                     double vfov_rad) {
  CameraIntrinsics camera;
  camera.width = width_px;
  camera.height = height_px;
  if (width_px <= 0 || height_px <= 0 || !(hfov_rad > 0.0) || !(vfov_rad > 0.0)) return camera;
  camera.fx = 0.5 * width_px / std::tan(0.5 * hfov_rad);
  camera.fy = 0.5 * height_px / std::tan(0.5 * vfov_rad);
  camera.cx = 0.5 * (width_px - 1);
  camera.cy = 0.5 * (height_px - 1);
  return camera;
}

}  // namespace facet::openni2
