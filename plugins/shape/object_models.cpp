#include "shape/object_models.hpp"

#include "shape/object_points.hpp"
#include "shape/pca_box.hpp"
#include "shape/support_plane.hpp"

namespace facet::shape {

const ObjectStageContract kObjectStage{
    In<LabelImage>{"objects", "Object ids 1..N, CV_32SC1; 0 = not an object."},
    In<PointImage>{"points", "3D points, CV_32FC3 in metres, NaN = invalid; same size."},
    OptionalIn<SupportPlanes>{
        "planes",
        "Support planes. When given, each object records the plane its lowest points rest on."},
    Out<ObjectList>{"objects",
                    "Per object: id, pixel count, centroid, axis-aligned bounds, PCA box, support "
                    "plane (id and equation), shape model, grasp prototype (metres, camera "
                    "frame)."},
    Param<double>{
        "support_tolerance_m",
        0.02,
        "An object rests on a plane when its lowest points (2nd percentile of the "
        "signed distance) are within this of it and most of it lies above.",
        {.unit = "m", .min = 0.0, .max = 1.0, .origin = "a few depth-noise widths at 1 m"}},
    Param<double>{
        "support_max_gap_m",
        0.3,
        "An object also stands on a horizontal plane when its lowest visible points are "
        "up to this far above it (only its top is seen); the nearest plane below wins.",
        {.unit = "m", .min = 0.0, .max = 10.0, .origin = "taller than graspable objects"}}};

std::vector<ObjectGeometry> describe_objects(const LabelImage& objects, const PointImage& points,
                                             const SupportPlanes* planes,
                                             double support_tolerance_m, double support_max_gap_m) {
  std::vector<ObjectGeometry> out;
  for (ObjectPoints& gathered : gather_object_points(objects.labels, points.points)) {
    ObjectGeometry geometry;
    ObjectModel& model = geometry.model;
    model.id = gathered.id;
    model.pixel_count = gathered.pixel_count;
    geometry.points_m = std::move(gathered.points);
    if (!geometry.points_m.empty()) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (const Eigen::Vector3d& p : geometry.points_m) {
        sum += p;
        model.bounds_m.extend(p);
      }
      model.centroid_m = sum / static_cast<double>(geometry.points_m.size());
      model.box = fit_pca_box(geometry.points_m);
    }
    if (planes != nullptr) {
      geometry.support = find_support_plane(geometry.points_m, planes->planes, support_tolerance_m,
                                            support_max_gap_m);
      if (geometry.support != nullptr) {
        model.support_plane = geometry.support->id;
        model.support_normal = geometry.support->normal;
        model.support_offset_m = geometry.support->offset_m;
      }
    }
    out.push_back(std::move(geometry));
  }
  return out;
}

}  // namespace facet::shape
