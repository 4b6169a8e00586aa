#include "synthetic/primitives.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "synthetic/shells.hpp"

namespace facet::synthetic {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double max_component(const Vec3& v) {
  return std::max({v[0], v[1], v[2]});
}

// Slab test against the axis-aligned box |p| <= half in local coordinates: the entry and exit
// parameters, and the axis of the entry face.
struct SlabSpan {
  double enter = -kInfinity;
  double exit = kInfinity;
  int enter_axis = 0;
};

std::optional<SlabSpan> slab_span(const Vec3& origin, const Vec3& direction, const Vec3& half) {
  SlabSpan span;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(direction[axis]) < 1e-15) {
      if (std::abs(origin[axis]) > half[axis]) return std::nullopt;
      continue;
    }
    double near = (-half[axis] - origin[axis]) / direction[axis];
    double far = (half[axis] - origin[axis]) / direction[axis];
    if (near > far) std::swap(near, far);
    if (near > span.enter) {
      span.enter = near;
      span.enter_axis = axis;
    }
    span.exit = std::min(span.exit, far);
    if (span.enter > span.exit) return std::nullopt;
  }
  return span;
}

std::optional<RayHit> hit_box(const Vec3& o, const Vec3& d, const Vec3& half, double t_min,
                              double t_max) {
  const auto span = slab_span(o, d, half);
  if (!span || span->enter <= t_min || span->enter >= t_max) return std::nullopt;
  RayHit hit{span->enter, Vec3(0, 0, 0)};
  hit.normal[span->enter_axis] = d[span->enter_axis] > 0 ? -1.0 : 1.0;
  return hit;
}

// Signed distance to a box of half extents `inner` grown by `rounding` (a rounded box).
double rounded_box_distance(const Vec3& p, const Vec3& inner, double rounding) {
  const Vec3 q(std::abs(p[0]) - inner[0], std::abs(p[1]) - inner[1], std::abs(p[2]) - inner[2]);
  const Vec3 outside(std::max(q[0], 0.0), std::max(q[1], 0.0), std::max(q[2], 0.0));
  return cv::norm(outside) + std::min(max_component(q), 0.0) - rounding;
}

Vec3 rounded_box_normal(const Vec3& p, const Vec3& inner) {
  Vec3 n;
  for (int axis = 0; axis < 3; ++axis) {
    const double excess = std::abs(p[axis]) - inner[axis];
    n[axis] = excess > 0.0 ? std::copysign(excess, p[axis]) : 0.0;
  }
  const double length = cv::norm(n);
  if (length > 0.0) return n / length;
  // Inside the inner box (only reached by rounding errors): the nearest face's normal.
  int axis = 0;
  double best = kInfinity;
  for (int a = 0; a < 3; ++a) {
    const double gap = inner[a] - std::abs(p[a]);
    if (gap < best) {
      best = gap;
      axis = a;
    }
  }
  Vec3 face(0, 0, 0);
  face[axis] = std::copysign(1.0, p[axis]);
  return face;
}

// Sphere tracing of the exact distance function, started where the ray enters the bounding box.
std::optional<RayHit> hit_rounded_box(const Vec3& o, const Vec3& d, const Vec3& half,
                                      double rounding, double t_min, double t_max) {
  const auto span = slab_span(o, d, half);
  if (!span || span->exit <= t_min || span->enter >= t_max) return std::nullopt;
  const Vec3 inner = half - Vec3(rounding, rounding, rounding);
  const double speed = cv::norm(d);
  double t = std::max(span->enter, t_min);
  const double t_end = std::min(span->exit, t_max);
  for (int step = 0; step < 96 && t <= t_end; ++step) {
    const Vec3 p = o + t * d;
    const double distance = rounded_box_distance(p, inner, rounding);
    if (distance < 1e-6) {
      if (t <= t_min) return std::nullopt;
      return RayHit{t, rounded_box_normal(p, inner)};
    }
    t += distance / speed;
  }
  return std::nullopt;
}

std::optional<RayHit> hit_cylinder(const Vec3& o, const Vec3& d, double radius, double half_length,
                                   double t_min, double t_max) {
  std::optional<RayHit> best;
  auto consider = [&](double t, const Vec3& normal) {
    if (t > t_min && t < t_max && (!best || t < best->t)) best = RayHit{t, normal};
  };
  // Mantle: x^2 + y^2 = r^2 with |z| <= half length.
  const double a = d[0] * d[0] + d[1] * d[1];
  if (a > 1e-18) {
    const double b = 2.0 * (o[0] * d[0] + o[1] * d[1]);
    const double c = o[0] * o[0] + o[1] * o[1] - radius * radius;
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant >= 0.0) {
      const double root = std::sqrt(discriminant);
      for (const double t : {(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)}) {
        const Vec3 p = o + t * d;
        if (std::abs(p[2]) <= half_length) consider(t, Vec3(p[0], p[1], 0.0) / radius);
      }
    }
  }
  // Caps.
  if (std::abs(d[2]) > 1e-15) {
    for (const double side : {-1.0, 1.0}) {
      const double t = (side * half_length - o[2]) / d[2];
      const Vec3 p = o + t * d;
      if (p[0] * p[0] + p[1] * p[1] <= radius * radius) consider(t, Vec3(0, 0, side));
    }
  }
  return best;
}

std::optional<RayHit> hit_sphere(const Vec3& o, const Vec3& d, double radius, double t_min,
                                 double t_max) {
  const double a = d.dot(d);
  const double b = 2.0 * o.dot(d);
  const double c = o.dot(o) - radius * radius;
  const double discriminant = b * b - 4.0 * a * c;
  if (discriminant < 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  for (const double t : {(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)}) {
    if (t > t_min && t < t_max) return RayHit{t, (o + t * d) / radius};
  }
  return std::nullopt;
}

std::optional<RayHit> hit_plane(const Vec3& o, const Vec3& d, double t_min, double t_max) {
  if (std::abs(d[2]) < 1e-15) return std::nullopt;
  const double t = -o[2] / d[2];
  if (t <= t_min || t >= t_max) return std::nullopt;
  return RayHit{t, Vec3(0, 0, 1)};
}

}  // namespace

double Solid::bounding_radius() const {
  switch (shape) {
    case Shape::box:
    case Shape::rounded_box:
      return cv::norm(half_size);
    case Shape::cylinder:
      return std::hypot(half_size[0], half_size[2]);
    case Shape::sphere:
      return half_size[0];
    case Shape::cup:
      return std::hypot(half_size[0], half_size[2]);
    case Shape::bowl:
      return std::hypot(bowl_rim_radius(half_size[0], half_size[2], wall), half_size[2]);
    case Shape::plane:
      return kInfinity;
  }
  return kInfinity;
}

std::optional<RayHit> Solid::intersect(const Ray& ray, double t_min, double t_max) const {
  // Cheap rejection: the ray misses the bounding sphere.
  const Vec3 to_centre = centre - ray.origin;
  if (shape != Shape::plane) {
    const double radius = bounding_radius();
    const double along = to_centre.dot(ray.direction) / ray.direction.dot(ray.direction);
    const Vec3 closest = ray.origin + along * ray.direction - centre;
    if (closest.dot(closest) > radius * radius) return std::nullopt;
  }
  const Mat3 to_local = rotation.t();
  const Vec3 o = to_local * (ray.origin - centre);
  const Vec3 d = to_local * ray.direction;
  std::optional<RayHit> hit;
  switch (shape) {
    case Shape::box:
      hit = hit_box(o, d, half_size, t_min, t_max);
      break;
    case Shape::rounded_box:
      hit = hit_rounded_box(o, d, half_size, rounding, t_min, t_max);
      break;
    case Shape::cylinder:
      hit = hit_cylinder(o, d, half_size[0], half_size[2], t_min, t_max);
      break;
    case Shape::sphere:
      hit = hit_sphere(o, d, half_size[0], t_min, t_max);
      break;
    case Shape::plane:
      hit = hit_plane(o, d, t_min, t_max);
      break;
    case Shape::cup:
      hit = hit_cup(o, d, half_size[0], half_size[2], wall, t_min, t_max);
      break;
    case Shape::bowl:
      hit = hit_bowl(o, d, half_size[0], half_size[2], wall, t_min, t_max);
      break;
  }
  if (hit) hit->normal = rotation * hit->normal;
  return hit;
}

Mat3 yaw_rotation(double yaw_rad) {
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  return Mat3(c, -s, 0, s, c, 0, 0, 0, 1);
}

Mat3 lying_rotation(double yaw_rad) {
  // Local z along the heading (cos, sin, 0), local x = world z, local y completes the frame.
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  const Vec3 z_axis(c, s, 0);
  const Vec3 x_axis(0, 0, 1);
  const Vec3 y_axis = z_axis.cross(x_axis);
  return Mat3(x_axis[0], y_axis[0], z_axis[0], x_axis[1], y_axis[1], z_axis[1], x_axis[2],
              y_axis[2], z_axis[2]);
}

}  // namespace facet::synthetic
