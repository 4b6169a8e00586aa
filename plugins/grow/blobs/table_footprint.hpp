#pragma once
// "Objects stand inside the table": whether a point's footprint, its projection along world up
// onto the table plane, lies inside the table's outline (planes.support's table_outline_m)
// grown by a margin. Things seen beyond the table (a chair, the floor, a wall's shreds) stand
// outside it.

#include <Eigen/Core>
#include <vector>

#include "facet/types/geometry.hpp"

namespace facet::blobs {

class TableFootprint {
 public:
  // Nothing is inside when the planes have no table or no outline (valid() is false).
  TableFootprint(const SupportPlanes& planes, float margin_m);

  bool valid() const { return !edges_.empty(); }
  // xyz: camera frame, metres.
  bool contains(const float* xyz) const;

 private:
  struct Edge {
    Eigen::Vector2f start;
    Eigen::Vector2f inward;  // unit normal of the edge, into the polygon
  };
  Eigen::Vector3f origin_ = Eigen::Vector3f::Zero();
  Eigen::Vector3f e1_ = Eigen::Vector3f::UnitX();
  Eigen::Vector3f e2_ = Eigen::Vector3f::UnitY();
  std::vector<Edge> edges_;
  float margin_m_ = 0.0F;
};

}  // namespace facet::blobs
