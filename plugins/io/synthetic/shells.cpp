#include "synthetic/shells.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace facet::synthetic {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The part of a ray inside a solid: from `enter` to `exit` (ray parameters), with the solid's
// outward normal at both ends. Infinite ends carry no normal that is ever used.
struct Span {
  double enter = -kInfinity;
  double exit = kInfinity;
  Vec3 enter_normal;
  Vec3 exit_normal;
};

// At most two spans: what is left of one span after another is cut out of it.
struct Spans {
  std::array<Span, 2> items;
  int count = 0;
  void add(const Span& span) {
    if (span.enter < span.exit) items[static_cast<std::size_t>(count++)] = span;
  }
};

// The ray parameters between the roots of a t^2 + b t + c (a > 0), where the quadric that gives
// those coefficients is negative: inside it. No span when the ray only touches or misses it.
std::optional<Span> between_roots(double a, double b, double c) {
  const double discriminant = b * b - 4.0 * a * c;
  if (discriminant <= 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  Span span;
  span.enter = (-b - root) / (2.0 * a);
  span.exit = (-b + root) / (2.0 * a);
  return span;
}

// Inside the sphere of `radius` about `centre`.
std::optional<Span> sphere_span(const Vec3& o, const Vec3& d, const Vec3& centre, double radius) {
  const Vec3 oc = o - centre;
  std::optional<Span> inside =
      between_roots(d.dot(d), 2.0 * oc.dot(d), oc.dot(oc) - radius * radius);
  if (!inside) return std::nullopt;
  Span& span = *inside;
  span.enter_normal = (oc + span.enter * d) / radius;
  span.exit_normal = (oc + span.exit * d) / radius;
  return inside;
}

// Inside the infinite cylinder x^2 + y^2 <= radius^2.
std::optional<Span> cylinder_span(const Vec3& o, const Vec3& d, double radius) {
  const double a = d[0] * d[0] + d[1] * d[1];
  const double c = o[0] * o[0] + o[1] * o[1] - radius * radius;
  if (a < 1e-18) {
    if (c > 0.0) return std::nullopt;
    return Span{};  // parallel to the axis and inside: all of the ray
  }
  std::optional<Span> inside = between_roots(a, 2.0 * (o[0] * d[0] + o[1] * d[1]), c);
  if (!inside) return std::nullopt;
  Span& span = *inside;
  const Vec3 p0 = o + span.enter * d;
  const Vec3 p1 = o + span.exit * d;
  span.enter_normal = Vec3(p0[0], p0[1], 0.0) / radius;
  span.exit_normal = Vec3(p1[0], p1[1], 0.0) / radius;
  return inside;
}

// Inside the horizontal slab low <= z <= high.
std::optional<Span> slab_span(const Vec3& o, const Vec3& d, double low, double high) {
  if (std::abs(d[2]) < 1e-15) {
    if (o[2] < low || o[2] > high) return std::nullopt;
    return Span{};
  }
  Span span;
  const double t_low = (low - o[2]) / d[2];
  const double t_high = (high - o[2]) / d[2];
  if (t_low < t_high) {
    span = {t_low, t_high, Vec3(0, 0, -1), Vec3(0, 0, 1)};
  } else {
    span = {t_high, t_low, Vec3(0, 0, 1), Vec3(0, 0, -1)};
  }
  return span;
}

std::optional<Span> intersect(const std::optional<Span>& a, const std::optional<Span>& b) {
  if (!a || !b) return std::nullopt;
  Span span;
  if (a->enter >= b->enter) {
    span.enter = a->enter;
    span.enter_normal = a->enter_normal;
  } else {
    span.enter = b->enter;
    span.enter_normal = b->enter_normal;
  }
  if (a->exit <= b->exit) {
    span.exit = a->exit;
    span.exit_normal = a->exit_normal;
  } else {
    span.exit = b->exit;
    span.exit_normal = b->exit_normal;
  }
  if (span.enter >= span.exit) return std::nullopt;
  return span;
}

// `solid` without `hole`: where the hole's surface bounds what is left, the outward normal of
// the remainder points into the hole, against the hole's own outward normal.
Spans subtract(const std::optional<Span>& solid, const std::optional<Span>& hole) {
  Spans result;
  if (!solid) return result;
  if (!hole || hole->exit <= solid->enter || hole->enter >= solid->exit) {
    result.add(*solid);
    return result;
  }
  if (hole->enter > solid->enter) {
    result.add({solid->enter, hole->enter, solid->enter_normal, -hole->enter_normal});
  }
  if (hole->exit < solid->exit) {
    result.add({hole->exit, solid->exit, -hole->exit_normal, solid->exit_normal});
  }
  return result;
}

// The first boundary of the spans the ray crosses in (t_min, t_max): an entry for a ray that
// starts outside, an exit for one that starts inside (a shadow ray leaving a surface).
std::optional<RayHit> first_boundary(const Spans& spans, double t_min, double t_max) {
  std::optional<RayHit> best;
  auto consider = [&](double t, const Vec3& normal) {
    if (t > t_min && t < t_max && (!best || t < best->t)) best = RayHit{t, normal};
  };
  for (int i = 0; i < spans.count; ++i) {
    const Span& span = spans.items[static_cast<std::size_t>(i)];
    consider(span.enter, span.enter_normal);
    consider(span.exit, span.exit_normal);
  }
  return best;
}

}  // namespace

std::optional<RayHit> hit_cup(const Vec3& origin, const Vec3& direction, double radius,
                              double half_height, double wall, double t_min, double t_max) {
  const auto outer = intersect(cylinder_span(origin, direction, radius),
                               slab_span(origin, direction, -half_height, half_height));
  // The hole: the inner cylinder from the top of the bottom up, open above the rim.
  const auto hole = intersect(cylinder_span(origin, direction, radius - wall),
                              slab_span(origin, direction, -half_height + wall, half_height + 1.0));
  return first_boundary(subtract(outer, hole), t_min, t_max);
}

double bowl_sphere_centre_z(double sphere_radius, double half_height, double wall) {
  return -half_height + sphere_radius - 0.5 * wall;
}

double bowl_rim_radius(double sphere_radius, double half_height, double wall) {
  const double below_centre = bowl_sphere_centre_z(sphere_radius, half_height, wall) - half_height;
  return std::sqrt(std::max(sphere_radius * sphere_radius - below_centre * below_centre, 0.0));
}

double bowl_foot_radius(double sphere_radius, double wall) {
  const double below_centre = sphere_radius - 0.5 * wall;
  return std::sqrt(std::max(sphere_radius * sphere_radius - below_centre * below_centre, 0.0));
}

std::optional<RayHit> hit_bowl(const Vec3& origin, const Vec3& direction, double sphere_radius,
                               double half_height, double wall, double t_min, double t_max) {
  const Vec3 centre(0.0, 0.0, bowl_sphere_centre_z(sphere_radius, half_height, wall));
  const auto outer = intersect(sphere_span(origin, direction, centre, sphere_radius),
                               slab_span(origin, direction, -half_height, half_height));
  const auto hole = sphere_span(origin, direction, centre, sphere_radius - wall);
  return first_boundary(subtract(outer, hole), t_min, t_max);
}

}  // namespace facet::synthetic
