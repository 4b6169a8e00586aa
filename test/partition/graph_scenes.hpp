#pragma once
// Scenes for partition.graph: objects on a rendered table (so that a gap between two objects
// shows the table behind them), blobs as the connected parts of each object (an occluder cuts an
// object into two blobs, as grow.blobs does), patches as the connected parts of each face, and
// an open bowl (a hemispherical shell) ray-cast beside the scene builder's primitives.

#include "partition_scene.hpp"

namespace facet::test {

// Relabels every 8-connected part of each non-zero id of `ids` with its own id 1..N, in raster
// order of each part's first pixel; ids listed in `dropped` become 0.
inline cv::Mat connected_parts(const cv::Mat& ids, const std::set<std::int32_t>& dropped = {}) {
  cv::Mat out = cv::Mat::zeros(ids.size(), CV_32SC1);
  std::int32_t next = 1;
  for (int v = 0; v < ids.rows; ++v) {
    for (int u = 0; u < ids.cols; ++u) {
      const std::int32_t id = ids.at<std::int32_t>(v, u);
      if (id == 0 || dropped.count(id) > 0 || out.at<std::int32_t>(v, u) != 0) continue;
      std::vector<cv::Point> stack{{u, v}};
      out.at<std::int32_t>(v, u) = next;
      while (!stack.empty()) {
        const cv::Point p = stack.back();
        stack.pop_back();
        for (int dv = -1; dv <= 1; ++dv) {
          for (int du = -1; du <= 1; ++du) {
            const cv::Point q(p.x + du, p.y + dv);
            if (q.x < 0 || q.y < 0 || q.x >= ids.cols || q.y >= ids.rows) continue;
            if (ids.at<std::int32_t>(q) != id || out.at<std::int32_t>(q) != 0) continue;
            out.at<std::int32_t>(q) = next;
            stack.push_back(q);
          }
        }
      }
      ++next;
    }
  }
  return out;
}

// Blobs as grow.blobs makes them: 8-connected pixels of `mask` whose points are closer than
// `max_step_m`, ids 1..N in raster order; parts under `min_px` pixels are dropped (0).
inline cv::Mat blobs_by_distance(const cv::Mat& points, const cv::Mat& mask, double max_step_m,
                                 std::int32_t min_px = 50) {
  cv::Mat out = cv::Mat::zeros(mask.size(), CV_32SC1);
  std::int32_t next = 1;
  for (int v = 0; v < mask.rows; ++v) {
    for (int u = 0; u < mask.cols; ++u) {
      if (mask.at<std::uint8_t>(v, u) == 0 || out.at<std::int32_t>(v, u) != 0) continue;
      std::vector<cv::Point> stack{{u, v}};
      std::vector<cv::Point> part;
      out.at<std::int32_t>(v, u) = next;
      while (!stack.empty()) {
        const cv::Point p = stack.back();
        stack.pop_back();
        part.push_back(p);
        const cv::Vec3f& a = points.at<cv::Vec3f>(p);
        for (int dv = -1; dv <= 1; ++dv) {
          for (int du = -1; du <= 1; ++du) {
            const cv::Point q(p.x + du, p.y + dv);
            if (q.x < 0 || q.y < 0 || q.x >= mask.cols || q.y >= mask.rows) continue;
            if (mask.at<std::uint8_t>(q) == 0 || out.at<std::int32_t>(q) != 0) continue;
            if (cv::norm(points.at<cv::Vec3f>(q) - a) >= max_step_m) continue;
            out.at<std::int32_t>(q) = next;
            stack.push_back(q);
          }
        }
      }
      if (static_cast<std::int32_t>(part.size()) < min_px) {
        for (const cv::Point& p : part)
          out.at<std::int32_t>(p) = -1;  // visited, no blob
        continue;
      }
      ++next;
    }
  }
  out.setTo(0, out < 0);
  return out;
}

// The table plane of a Tabletop as a scene primitive.
inline void add_table(const Tabletop& table, SceneBuilder& builder) {
  const Eigen::Isometry3d origin = table.pose(0.0, 0.0, 0.0);
  builder.plane(origin.translation(), origin.linear() * Eigen::Vector3d::UnitZ());
}

// An open hemispherical bowl standing on the table: outer radius `radius_m`, wall `wall_m`, its
// rim at height radius_m above the table. Faces: outside and rim (one face, as grow.surfaces
// would give the thin rim to a neighbour) = first_face, inside = first_face + 1. With
// `floor_depth_m` > 0 the inside has a flat floor that deep below the rim (a pot): face
// first_face + 2.
inline void add_bowl(RenderedScene& scene, const Tabletop& table, double x_m, double y_m,
                     double radius_m, double wall_m, std::int32_t object_id,
                     std::int32_t first_face, double floor_depth_m = 0.0) {
  const Eigen::Isometry3d pose = table.pose(x_m, y_m, radius_m);  // rim centre
  const Eigen::Isometry3d to_local = pose.inverse();
  const double inner_m = radius_m - wall_m;
  const CameraIntrinsics& c = scene.camera;
  for (int v = 0; v < c.height; ++v) {
    for (int u = 0; u < c.width; ++u) {
      const Eigen::Vector3d ray((u - c.cx) / c.fx, (v - c.cy) / c.fy, 1.0);
      const Eigen::Vector3d o = to_local.translation();
      const Eigen::Vector3d d = to_local.linear() * ray;
      double best = std::numeric_limits<double>::infinity();
      std::int32_t face = 0;
      // The shell is r_in <= |x| <= r_out, z <= 0: the first crossing of its boundary is what the
      // camera sees.
      for (const auto& [r, id] :
           {std::pair{radius_m, first_face}, std::pair{inner_m, first_face + 1}}) {
        const double b = o.dot(d);
        const double cc = o.squaredNorm() - r * r;
        const double disc = b * b - d.squaredNorm() * cc;
        if (disc < 0.0) continue;
        for (const double sign : {-1.0, 1.0}) {
          const double t = (-b + sign * std::sqrt(disc)) / d.squaredNorm();
          const double z = (o + t * d).z();
          const bool under_floor = floor_depth_m > 0.0 && id != first_face && z < -floor_depth_m;
          if (t > 0.0 && z <= 0.0 && !under_floor && t < best) {
            best = t;
            face = id;
          }
        }
      }
      if (std::abs(d.z()) > 1e-12) {
        const double t = -o.z() / d.z();
        const double rho = (o + t * d).head<2>().norm();
        if (t > 0.0 && rho >= inner_m && rho <= radius_m && t < best) {
          best = t;
          face = first_face;
        }
      }
      if (floor_depth_m > 0.0 && std::abs(d.z()) > 1e-12) {
        const double t = (-floor_depth_m - o.z()) / d.z();
        const double rho = (o + t * d).head<2>().norm();
        const double floor_radius_m =
            std::sqrt(std::max(inner_m * inner_m - floor_depth_m * floor_depth_m, 0.0));
        if (t > 0.0 && rho <= floor_radius_m && t < best) {
          best = t;
          face = first_face + 2;
        }
      }
      if (face == 0) continue;
      float& depth = scene.depth_m.at<float>(v, u);
      if (depth > 0.0F && depth <= best) continue;
      depth = static_cast<float>(best);
      scene.object.at<std::int32_t>(v, u) = object_id;
      scene.face.at<std::int32_t>(v, u) = face;
    }
  }
}

// Stage input from a scene whose object `table_object` (0: none) is the table: the table is no
// blob and no patch (planes.support removed it), blobs are grown over steps under 10 mm (as
// grow.blobs does), every connected part of a face is a patch.
inline PartitionInput graph_input(const RenderedScene& scene, std::int32_t table_object) {
  PartitionInput input;
  input.scene = scene;
  cv::Mat objects = scene.object.clone();
  cv::Mat faces = scene.face.clone();
  if (table_object > 0) {
    faces.setTo(0, scene.object == table_object);
    objects.setTo(0, scene.object == table_object);
  }
  input.points = back_project(scene);
  input.blobs = label_image(blobs_by_distance(input.points.points, objects > 0, 0.01));
  input.patches = label_image(connected_parts(faces));
  input.adjacency = contacts_of(input.patches.labels);
  return input;
}

// The scene's bodies without the table, for matches_bodies.
inline cv::Mat bodies_without(const RenderedScene& scene, std::int32_t table_object) {
  cv::Mat bodies = scene.object.clone();
  if (table_object > 0) bodies.setTo(0, scene.object == table_object);
  return bodies;
}

}  // namespace facet::test
