#pragma once
// When two neighbouring pixels' points are close enough to be one blob (paper sec. II-B e:
// Delta_blob), shared by grow.blobs' region growing and edge attachment and by planes.support's
// split of what a plane leaves of a patch.
//
// A depth camera's depth step grows with the square of the depth: a Kinect's disparity steps
// are 3 mm apart at 1 m, 11 mm at 2 m and 26 mm at 3 m, and stereo cameras behave alike. A fixed
// Delta_blob of 10 mm therefore cuts every surface beyond about 1.7 m into stripes, one per step,
// and every object there falls apart below the blob size. So beyond `growth_start_m` the
// distance grows with the square of the nearer point's depth.

namespace facet::algo {

class NeighbourGate {
 public:
  // growth_start_m <= 0: the distance is the same at every depth.
  NeighbourGate(float max_distance_m, float growth_start_m)
      : max_distance_m_(max_distance_m),
        inverse_start_m_(growth_start_m > 0.0F ? 1.0F / growth_start_m : 0.0F) {}

  // a, b: x, y, z in metres, finite.
  bool close(const float* a, const float* b) const {
    const float dx = a[0] - b[0];
    const float dy = a[1] - b[1];
    const float dz = a[2] - b[2];
    const float depth_ratio = (a[2] < b[2] ? a[2] : b[2]) * inverse_start_m_;
    const float growth = depth_ratio > 1.0F ? depth_ratio * depth_ratio : 1.0F;
    const float limit = max_distance_m_ * growth;
    return dx * dx + dy * dy + dz * dz < limit * limit;
  }

 private:
  float max_distance_m_;
  float inverse_start_m_;
};

}  // namespace facet::algo
