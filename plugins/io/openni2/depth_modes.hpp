#pragma once
// The depth video modes a device offers, which one a graph asks for, and the pinhole intrinsics
// of a stream from its field of view. Plain data, no OpenNI2: the rules are tested without a
// device.

#include <string>
#include <vector>

#include "facet/types/frame.hpp"

namespace facet::openni2 {

struct DepthMode {
  int width_px = 0;
  int height_px = 0;
  int fps = 0;
  std::string pixel_format;  // "1 mm", "100 um", "shift 9.2", ... (format_name())
  bool millimetres = false;  // CV_16UC1 in mm, the only format io.openni2 outputs

  bool operator==(const DepthMode&) const = default;
};

// "640x480 @ 30 fps, 1 mm"
std::string describe(const DepthMode& mode);

// What the graph asks for; 0 = any (all 0: the device's current mode).
struct ModeRequest {
  int width_px = 0;
  int height_px = 0;
  int fps = 0;

  bool empty() const { return width_px == 0 && height_px == 0 && fps == 0; }
};

// The mode to set: with an empty request `current` when it is in millimetres, else the first
// millimetre mode of `current`'s size and rate, else the first millimetre mode; with a request
// the first millimetre mode of `supported` that matches every field given. Throws
// facet::StageError naming `uri` and listing every supported mode when none fits.
DepthMode choose_depth_mode(const std::vector<DepthMode>& supported, const DepthMode& current,
                            const ModeRequest& request, const std::string& uri);

// Pinhole intrinsics of a width x height image seeing hfov x vfov (radians, full angles):
// fx = (width / 2) / tan(hfov / 2), likewise fy, and the principal point at the image centre in
// pixel-centre coordinates, ((width - 1) / 2, (height - 1) / 2). OpenNI2 reports nothing finer.
CameraIntrinsics intrinsics_from_fov(int width_px, int height_px, double hfov_rad, double vfov_rad);

}  // namespace facet::openni2
