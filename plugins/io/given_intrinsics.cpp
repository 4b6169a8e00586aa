#include "io/given_intrinsics.hpp"

#include "facet/error.hpp"

namespace facet::io {

GivenIntrinsics::GivenIntrinsics(const std::string& when_not_given)
    : fx_{"fx", 0.0, "Focal length in x; 0 = " + when_not_given + ".", {.unit = "px", .min = 0.0}},
      fy_{"fy", 0.0, "Focal length in y; 0 = " + when_not_given + ".", {.unit = "px", .min = 0.0}},
      cx_{"cx", 0.0, "Principal point x (used when fx is given).", {.unit = "px"}},
      cy_{"cy", 0.0, "Principal point y (used when fx is given).", {.unit = "px"}} {}

void GivenIntrinsics::declare_in(StageSpec& spec) const {
  spec.declare(fx_, fy_, cx_, cy_);
}

CameraIntrinsics GivenIntrinsics::operator()(const Params& params) const {
  CameraIntrinsics given;
  given.fx = fx_(params);
  given.fy = fy_(params);
  given.cx = cx_(params);
  given.cy = cy_(params);
  if ((given.fx > 0.0) != (given.fy > 0.0)) {
    throw StageError("params fx and fy must both be set (> 0) when either is");
  }
  return given;
}

}  // namespace facet::io
