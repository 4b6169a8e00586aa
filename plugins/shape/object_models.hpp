#pragma once
// What both shape stages share: ports, the support-plane parameter, and the per-object facts
// that do not depend on the shape model (pixel count, centroid, bounds, PCA box, support plane).

#include <Eigen/Core>
#include <vector>

#include "facet/stage_spec.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"

namespace facet::shape {

struct ObjectGeometry {
  ObjectModel model;
  std::vector<Eigen::Vector3d> points_m;  // the object's valid points
  const Plane* support = nullptr;         // into the SupportPlanes input, or nullptr
};

// Declares the inputs (objects, points, planes), the output (objects), support_tolerance_m and
// support_max_gap_m.
void declare_object_ports(StageSpec& spec);

// One entry per labelled object, in increasing id order. `planes` may be nullptr.
std::vector<ObjectGeometry> describe_objects(const LabelImage& objects, const PointImage& points,
                                             const SupportPlanes* planes,
                                             double support_tolerance_m, double support_max_gap_m);

}  // namespace facet::shape
