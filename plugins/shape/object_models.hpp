#pragma once
// What both shape stages share: ports, the support-plane parameter, and the per-object facts
// that do not depend on the shape model (pixel count, centroid, bounds, PCA box, support plane).

#include <Eigen/Core>
#include <vector>

#include "facet/contract.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"

namespace facet::shape {

struct ObjectGeometry {
  ObjectModel model;
  std::vector<Eigen::Vector3d> points_m;  // the object's valid points
  const Plane* support = nullptr;         // into the SupportPlanes input, or nullptr
};

// The ports both shape stages have (inputs objects, points and planes, output objects) and their
// support parameters (support_tolerance_m, support_max_gap_m), declared in that order.
struct ObjectStageContract {
  In<LabelImage> objects;
  In<PointImage> points;
  OptionalIn<SupportPlanes> planes;
  Out<ObjectList> models;
  Param<double> support_tolerance_m;
  Param<double> support_max_gap_m;

  void declare_in(StageSpec& spec) const {
    spec.declare(objects, points, planes, models, support_tolerance_m, support_max_gap_m);
  }
};
extern const ObjectStageContract kObjectStage;

// One entry per labelled object, in increasing id order. `planes` may be nullptr.
std::vector<ObjectGeometry> describe_objects(const LabelImage& objects, const PointImage& points,
                                             const SupportPlanes* planes,
                                             double support_tolerance_m, double support_max_gap_m);

}  // namespace facet::shape
