#pragma once
// io.objects: writes each frame's object list as <dir>/<stem>.json (schema: docs/objects-json.md).

#include <filesystem>
#include <string>

#include "facet/stage.hpp"
#include "facet/types/geometry.hpp"
#include "io/output_folder.hpp"

namespace facet::io {

class ObjectsSink final : public Stage {
 public:
  static StageSpec spec();
  explicit ObjectsSink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
  EarlierResults earlier_;  // what the folder held before this run
};

// The file's "schema_version". 1 (files without the field): frame and objects only. 2: the
// frame's "camera" intrinsics and each object's "support_plane_equation".
inline constexpr int kObjectsJsonSchemaVersion = 2;

// The JSON text io.objects writes for one frame: deterministic (fixed key order, numbers with
// 9 significant digits, 2-space indentation), ending in a newline.
std::string objects_to_json(const ObjectList& list);

// The fields of one object in the order of the JSON text, handed to `out`, so that the text and
// other forms of the same object (the Python module's dicts) cannot drift apart. A Writer has
// open_object(key), open_array(key), close_object(), close_array(), number(key, double),
// numbers(key, Eigen vector), integer(key, long long), string(key, std::string_view) and
// null(key); an empty key is an element of the enclosing array.
template <class Writer>
void write_pose(Writer& out, const Eigen::Isometry3d& pose) {
  out.numbers("centre_m", pose.translation());
  const Eigen::Quaterniond q(pose.linear());
  out.numbers("quaternion_wxyz", Eigen::Vector4d(q.w(), q.x(), q.y(), q.z()));
  out.open_array("rotation");  // rows of the 3x3 matrix: box/superquadric axes are its columns
  for (int row = 0; row < 3; ++row)
    out.numbers({}, Eigen::Vector3d(pose.linear().row(row)));
  out.close_array();
}

template <class Writer>
void write_object(Writer& out, const ObjectModel& object) {
  out.open_object();
  out.integer("id", object.id);
  out.integer("pixel_count", object.pixel_count);
  out.numbers("centroid_m", object.centroid_m);
  if (object.bounds_m.isEmpty()) {
    out.null("bounds_m");
  } else {
    out.open_object("bounds_m");
    out.numbers("min", object.bounds_m.min());
    out.numbers("max", object.bounds_m.max());
    out.close_object();
  }
  out.open_object("box");
  write_pose(out, object.box.pose);
  out.numbers("half_extents_m", object.box.half_extents_m);
  out.number("residual_m", object.box.residual_m);
  out.close_object();
  out.integer("support_plane", object.support_plane);
  if (object.support_plane == 0) {
    out.null("support_plane_equation");
  } else {
    out.open_object("support_plane_equation");  // n·x + d = 0, n towards the camera
    out.numbers("normal", object.support_normal);
    out.number("offset_m", object.support_offset_m);
    out.close_object();
  }
  const Superquadric& sq = object.superquadric;
  if (!sq.valid) {
    out.null("superquadric");
  } else {
    out.open_object("superquadric");
    out.numbers("size_m", sq.size_m);
    out.number("epsilon1", sq.epsilon1);
    out.number("epsilon2", sq.epsilon2);
    write_pose(out, sq.pose);
    out.number("residual_m", sq.residual);
    out.close_object();
  }
  out.string("grasp", to_string(object.grasp));
  out.close_object();
}

}  // namespace facet::io
