// The layouts as solids: every object stands on the table or on a flat top, and no two solids
// share a volume (a point-in-solid test written here, independent of the ray caster).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "synthetic/scene_layout.hpp"
#include "synthetic/shells.hpp"

namespace {

using facet::synthetic::Scene;
using facet::synthetic::Shape;
using facet::synthetic::Solid;
using facet::synthetic::Vec3;

bool lies_down(const Solid& solid) {
  return solid.shape == Shape::cylinder && std::abs(solid.rotation(2, 2)) < 0.5;
}

// Half of the solid's vertical extent.
double half_height(const Solid& solid) {
  if (solid.shape == Shape::sphere || lies_down(solid)) return solid.half_size[0];
  return solid.half_size[2];
}

double bottom(const Solid& solid) {
  return solid.centre[2] - half_height(solid);
}
double top(const Solid& solid) {
  return solid.centre[2] + half_height(solid);
}

// Whether the world point lies inside the solid, shrunk by `margin` (so that touching solids,
// which share surface points, do not count as overlapping).
bool inside(const Solid& solid, const Vec3& world, double margin) {
  const Vec3 p = solid.rotation.t() * (world - solid.centre);
  const Vec3& h = solid.half_size;
  switch (solid.shape) {
    case Shape::box:
      return std::abs(p[0]) < h[0] - margin && std::abs(p[1]) < h[1] - margin &&
             std::abs(p[2]) < h[2] - margin;
    case Shape::rounded_box: {
      const double r = solid.rounding;
      double outside = 0.0;
      double inner = -1e9;
      for (int axis = 0; axis < 3; ++axis) {
        const double q = std::abs(p[axis]) - (h[axis] - r);
        outside += std::max(q, 0.0) * std::max(q, 0.0);
        inner = std::max(inner, q);
      }
      return std::sqrt(outside) + std::min(inner, 0.0) - r < -margin;
    }
    case Shape::cylinder:
      return std::hypot(p[0], p[1]) < h[0] - margin && std::abs(p[2]) < h[2] - margin;
    case Shape::sphere:
      return cv::norm(p) < h[0] - margin;
    case Shape::plane:
      return p[2] < -margin;
    case Shape::cup: {
      // Within the outer cylinder, and not in the hole above the bottom.
      const double radial = std::hypot(p[0], p[1]);
      const bool in_outer = radial < h[0] - margin && std::abs(p[2]) < h[2] - margin;
      const bool in_hole =
          radial <= h[0] - solid.wall + margin && p[2] >= -h[2] + solid.wall - margin;
      return in_outer && !in_hole;
    }
    case Shape::bowl: {
      // Between the two spheres, between the foot and rim planes.
      const Vec3 centre(0, 0, facet::synthetic::bowl_sphere_centre_z(h[0], h[2], solid.wall));
      const double r = cv::norm(p - centre);
      return r < h[0] - margin && r > h[0] - solid.wall + margin && std::abs(p[2]) < h[2] - margin;
    }
  }
  return false;
}

// The footprint of a box-like solid contains the world point (x, y).
bool over_top(const Solid& base, const Vec3& point) {
  const Vec3 p = base.rotation.t() * (point - base.centre);
  if (base.shape == Shape::cylinder && !lies_down(base))
    return std::hypot(p[0], p[1]) <= base.half_size[0];
  return std::abs(p[0]) <= base.half_size[0] && std::abs(p[1]) <= base.half_size[1];
}

Scene scene_of(const std::string& preset, std::uint64_t seed) {
  facet::synthetic::RandomStream random(seed);
  return facet::synthetic::layout_scene(preset, {}, random);
}

TEST(SyntheticLayout, EveryObjectStandsOnTheTableOrOnAFlatTop) {
  for (const std::string& preset : facet::synthetic::preset_names()) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      SCOPED_TRACE(preset + " seed " + std::to_string(seed));
      const Scene scene = scene_of(preset, seed);
      const auto range = facet::synthetic::preset_object_range(preset);
      ASSERT_GE(scene.object_count, range.min);
      ASSERT_LE(scene.object_count, range.max);
      int stacked = 0;
      for (const auto& item : scene.solids) {
        if (item.label == 0) continue;
        const double z = bottom(item.solid);
        if (std::abs(z) < 1e-9) continue;
        ++stacked;
        // Not on the table: then on a box-like top at exactly its height, over that top.
        const bool supported =
            std::any_of(scene.solids.begin(), scene.solids.end(), [&](const auto& other) {
              return other.label != 0 && &other != &item && other.solid.shape != Shape::sphere &&
                     !lies_down(other.solid) && std::abs(top(other.solid) - z) < 1e-9 &&
                     over_top(other.solid, item.solid.centre);
            });
        EXPECT_TRUE(supported) << "object " << item.label << " floats at z = " << z;
      }
      // The classic presets stack exactly these; the hard cases are checked in hard_case_test.
      if (range.min == range.max) {
        EXPECT_EQ(stacked, preset == "stacked_occluded" ? 4 : 0);
      }
    }
  }
}

TEST(SyntheticLayout, NoTwoSolidsShareAVolume) {
  for (const std::string& preset : facet::synthetic::preset_names()) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE(preset + " seed " + std::to_string(seed));
      const Scene scene = scene_of(preset, seed);
      for (std::size_t a = 0; a < scene.solids.size(); ++a) {
        const Solid& first = scene.solids[a].solid;
        if (scene.solids[a].label == 0) continue;
        // Sample the first solid's bounding cube; no sample inside both solids (nor below the
        // table top, the table's volume).
        const double reach = first.bounding_radius();
        constexpr int kSteps = 14;
        for (int i = 0; i <= kSteps; ++i) {
          for (int j = 0; j <= kSteps; ++j) {
            for (int k = 0; k <= kSteps; ++k) {
              const Vec3 p = first.centre + reach * Vec3(2.0 * i / kSteps - 1, 2.0 * j / kSteps - 1,
                                                         2.0 * k / kSteps - 1);
              if (!inside(first, p, 1e-4)) continue;
              EXPECT_GT(p[2], 0.0) << "object " << scene.solids[a].label << " in the table";
              for (std::size_t b = 0; b < scene.solids.size(); ++b) {
                if (b == a || scene.solids[b].label == 0) continue;
                ASSERT_FALSE(inside(scene.solids[b].solid, p, 1e-4))
                    << "objects " << scene.solids[a].label << " and " << scene.solids[b].label
                    << " overlap at (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
              }
            }
          }
        }
      }
    }
  }
}

// Touching pairs touch: the two members of each pair are closer than a millimetre.
TEST(SyntheticLayout, TouchingPairsTouch) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Scene scene = scene_of("touching_pairs", seed);
    // Objects 1-2 and 3-4 are the pairs: a point of one solid just inside the other when grown.
    for (const auto& [first, second] : {std::pair{1, 2}, std::pair{3, 4}}) {
      const Solid* a = nullptr;
      const Solid* b = nullptr;
      for (const auto& item : scene.solids) {
        if (item.label == first) a = &item.solid;
        if (item.label == second) b = &item.solid;
      }
      ASSERT_TRUE(a && b);
      // Sample a's bounding cube densely; some point inside a (grown by 1 mm) is inside b grown
      // by 1 mm.
      bool close = false;
      const double reach = a->bounding_radius();
      constexpr int kSteps = 40;
      for (int i = 0; i <= kSteps && !close; ++i) {
        for (int j = 0; j <= kSteps && !close; ++j) {
          for (int k = 0; k <= kSteps && !close; ++k) {
            const Vec3 p = a->centre + reach * Vec3(2.0 * i / kSteps - 1, 2.0 * j / kSteps - 1,
                                                    2.0 * k / kSteps - 1);
            close = inside(*a, p, -0.003) && inside(*b, p, -0.003);
          }
        }
      }
      EXPECT_TRUE(close) << "objects " << first << " and " << second << " do not touch";
    }
  }
}

}  // namespace

namespace {

// With a wall, every object stands in front of it, the table ends at it and the wall is
// background.
TEST(SyntheticLayout, ObjectsStandInFrontOfTheWall) {
  facet::synthetic::RoomOptions room;
  room.wall = true;
  room.wall_distance_m = 0.35;
  for (const std::string& preset : facet::synthetic::preset_names()) {
    SCOPED_TRACE(preset);
    facet::synthetic::RandomStream random(3);
    const Scene scene = facet::synthetic::layout_scene(preset, room, random);
    int walls = 0;
    for (const auto& item : scene.solids) {
      if (item.solid.shape == Shape::plane && std::abs(item.solid.rotation(1, 2)) > 0.5) {
        ++walls;
        EXPECT_EQ(item.label, 0);
        EXPECT_DOUBLE_EQ(item.solid.centre[1], 0.35);
      }
      if (item.label == 0) continue;
      // Sample the solid's bounding cube: no point of it beyond the wall.
      const double reach = item.solid.bounding_radius();
      for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 10; ++j) {
          for (int k = 0; k <= 10; ++k) {
            const Vec3 p = item.solid.centre + reach * Vec3(0.2 * i - 1, 0.2 * j - 1, 0.2 * k - 1);
            if (inside(item.solid, p, 0.0)) {
              EXPECT_LT(p[1], 0.35) << "object " << item.label;
            }
          }
        }
      }
    }
    EXPECT_EQ(walls, 1);
  }
}

}  // namespace
