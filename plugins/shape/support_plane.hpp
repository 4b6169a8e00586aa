#pragma once
// Which support plane an object stands on: the plane its lowest points rest on.

#include <Eigen/Core>
#include <vector>

#include "facet/types/geometry.hpp"

namespace facet::shape {

// The plane (or nullptr) the object rests on. Its lowest points (the 2nd percentile of the signed
// distance, robust to a few stray pixels) must be above the plane or within tolerance_m below it,
// and most of the object (the median) on the camera side. A plane qualifies when that lowest
// point is within tolerance_m of it (contact seen), or when the plane is horizontal and the
// lowest point is at most max_gap_m above it: the camera often sees only an object's top, so its
// lowest visible point can be far above the table it stands on. The nearest qualifying plane
// wins; ties go to the earlier plane.
const Plane* find_support_plane(const std::vector<Eigen::Vector3d>& points_m,
                                const std::vector<Plane>& planes, double tolerance_m,
                                double max_gap_m);

}  // namespace facet::shape
