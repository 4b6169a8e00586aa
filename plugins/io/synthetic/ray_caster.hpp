#pragma once
// Renders a scene as a perfect depth camera would see it: one ray per pixel centre.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "synthetic/scene.hpp"

namespace facet::synthetic {

struct IdealFrame {
  cv::Mat depth_m;  // CV_64FC1, depth along the optical axis; 0 where the ray meets nothing
  cv::Mat labels;   // CV_32SC1, label of the solid hit (0 also where nothing is hit)
  cv::Mat points;   // CV_64FC3, world point hit
  cv::Mat normals;  // CV_64FC3, world unit normal there
};

// Rays go no farther than `max_depth_m` along the optical axis.
IdealFrame render_ideal(const Scene& scene, const CameraRig& rig, double max_depth_m);

// Visible pixels per label (index = label, 0..object_count).
std::vector<int> visible_pixels(const IdealFrame& frame, int object_count);

}  // namespace facet::synthetic
