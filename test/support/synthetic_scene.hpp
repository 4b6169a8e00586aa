#pragma once
// Exact depth images of simple geometry, for tests: planes, boxes and cylinders ray-cast through a
// pinhole camera. Every pixel takes the nearest hit; the result carries the depth (uint16 mm or
// float metres), the id of the primitive hit and the id of the face hit (a box has six faces, a
// cylinder a side and two caps, a plane one face).
//
// This is test support, independent of the stages it is used to test.

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <vector>

#include "facet/types/images.hpp"

namespace facet::test {

inline CameraIntrinsics kinect_camera() {
  return {525.0, 525.0, 319.5, 239.5, 640, 480};
}

struct RenderedScene {
  cv::Mat depth_m;  // CV_32FC1, 0 where nothing was hit
  cv::Mat object;   // CV_32SC1, primitive id (1-based in order of addition), 0 = nothing
  cv::Mat face;     // CV_32SC1, globally unique face id, 0 = nothing
  CameraIntrinsics camera;

  // Depth as a sensor delivers it: uint16 millimetres, 0 = invalid.
  DepthImage depth_mm_image() const {
    DepthImage image;
    image.camera = camera;
    depth_m.convertTo(image.depth, CV_16UC1, 1000.0);
    return image;
  }
  DepthImage depth_m_image() const {
    DepthImage image;
    image.camera = camera;
    image.depth = depth_m.clone();
    return image;
  }
};

class SceneBuilder {
 public:
  explicit SceneBuilder(CameraIntrinsics camera = kinect_camera()) : camera_(camera) {}

  // An infinite plane through `point` with normal `normal` (camera frame, metres).
  SceneBuilder& plane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = point;
    pose.linear() = rotation_to_z(normal.normalized());
    primitives_.push_back({Kind::plane, pose, Eigen::Vector3d::Zero(), next_face_});
    next_face_ += 1;
    return *this;
  }

  // A box with half extents `half_m` centred at `pose.translation()`, axes `pose.linear()`.
  SceneBuilder& box(const Eigen::Isometry3d& pose, const Eigen::Vector3d& half_m) {
    primitives_.push_back({Kind::box, pose, half_m, next_face_});
    next_face_ += 6;
    return *this;
  }

  // A closed cylinder along the pose's z axis, centred at the pose, radius half_m.x(), half
  // height half_m.z().
  SceneBuilder& cylinder(const Eigen::Isometry3d& pose, double radius_m, double half_height_m) {
    primitives_.push_back({Kind::cylinder, pose, {radius_m, radius_m, half_height_m}, next_face_});
    next_face_ += 3;
    return *this;
  }

  RenderedScene render() const {
    RenderedScene out;
    out.camera = camera_;
    out.depth_m = cv::Mat::zeros(camera_.height, camera_.width, CV_32FC1);
    out.object = cv::Mat::zeros(camera_.height, camera_.width, CV_32SC1);
    out.face = cv::Mat::zeros(camera_.height, camera_.width, CV_32SC1);
    for (int v = 0; v < camera_.height; ++v) {
      for (int u = 0; u < camera_.width; ++u) {
        const Eigen::Vector3d ray((u - camera_.cx) / camera_.fx, (v - camera_.cy) / camera_.fy,
                                  1.0);
        double best_t = std::numeric_limits<double>::infinity();
        int best_object = 0;
        int best_face = 0;
        for (std::size_t i = 0; i < primitives_.size(); ++i) {
          int face = 0;
          const double t = intersect(primitives_[i], ray, face);
          if (t > 0.0 && t < best_t) {
            best_t = t;
            best_object = static_cast<int>(i) + 1;
            best_face = primitives_[i].first_face + face;
          }
        }
        if (best_object == 0) continue;
        // The ray has z = 1, so t is the depth along the optical axis.
        out.depth_m.at<float>(v, u) = static_cast<float>(best_t);
        out.object.at<int>(v, u) = best_object;
        out.face.at<int>(v, u) = best_face;
      }
    }
    return out;
  }

 private:
  enum class Kind { plane, box, cylinder };
  struct Primitive {
    Kind kind;
    Eigen::Isometry3d pose;  // primitive frame → camera frame
    Eigen::Vector3d half;
    int first_face;
  };

  static Eigen::Matrix3d rotation_to_z(const Eigen::Vector3d& normal) {
    return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), normal).toRotationMatrix();
  }

  // Ray from the origin along `ray`; returns t > 0 of the nearest hit or -1, and the face index.
  static double intersect(const Primitive& p, const Eigen::Vector3d& ray, int& face) {
    const Eigen::Isometry3d to_local = p.pose.inverse();
    const Eigen::Vector3d o = to_local.translation();
    const Eigen::Vector3d d = to_local.linear() * ray;
    switch (p.kind) {
      case Kind::plane: {
        if (std::abs(d.z()) < 1e-12) return -1.0;
        face = 0;
        return -o.z() / d.z();
      }
      case Kind::box: {
        double t_near = -std::numeric_limits<double>::infinity();
        double t_far = std::numeric_limits<double>::infinity();
        int near_face = -1;
        for (int axis = 0; axis < 3; ++axis) {
          if (std::abs(d[axis]) < 1e-12) {
            if (std::abs(o[axis]) > p.half[axis]) return -1.0;
            continue;
          }
          double t0 = (-p.half[axis] - o[axis]) / d[axis];
          double t1 = (p.half[axis] - o[axis]) / d[axis];
          int f0 = 2 * axis;      // the -axis face
          int f1 = 2 * axis + 1;  // the +axis face
          if (t0 > t1) {
            std::swap(t0, t1);
            std::swap(f0, f1);
          }
          if (t0 > t_near) {
            t_near = t0;
            near_face = f0;
          }
          t_far = std::min(t_far, t1);
        }
        if (t_near > t_far || t_near <= 0.0) return -1.0;
        face = near_face;
        return t_near;
      }
      case Kind::cylinder: {
        const double r = p.half.x();
        const double h = p.half.z();
        double best = -1.0;
        // Side: x² + y² = r².
        const double a = d.x() * d.x() + d.y() * d.y();
        const double b = 2.0 * (o.x() * d.x() + o.y() * d.y());
        const double c = o.x() * o.x() + o.y() * o.y() - r * r;
        const double disc = b * b - 4.0 * a * c;
        if (a > 1e-12 && disc >= 0.0) {
          const double t = (-b - std::sqrt(disc)) / (2.0 * a);
          if (t > 0.0 && std::abs(o.z() + t * d.z()) <= h) {
            best = t;
            face = 0;
          }
        }
        // Caps: z = ±h.
        if (std::abs(d.z()) > 1e-12) {
          for (int side = 0; side < 2; ++side) {
            const double z = side == 0 ? -h : h;
            const double t = (z - o.z()) / d.z();
            const Eigen::Vector3d hit = o + t * d;
            if (t > 0.0 && hit.x() * hit.x() + hit.y() * hit.y() <= r * r &&
                (best < 0.0 || t < best)) {
              best = t;
              face = 1 + side;
            }
          }
        }
        return best;
      }
    }
    return -1.0;
  }

  CameraIntrinsics camera_;
  std::vector<Primitive> primitives_;
  int next_face_ = 1;
};

}  // namespace facet::test
