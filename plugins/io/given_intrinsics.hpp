#pragma once
// The pinhole intrinsics a user may give a source by hand, params fx, fy, cx, cy (pixels), for
// the sources that otherwise find them themselves (io.pcd fits them, io.openni2 reads the
// device's field of view). One descriptor, so that both name, document and check them alike.

#include <string>

#include "facet/contract.hpp"
#include "facet/stage_spec.hpp"
#include "facet/types/frame.hpp"

namespace facet::io {

class GivenIntrinsics {
 public:
  // `when_not_given` completes the focal lengths' docs ("0 = <when_not_given>."): what the
  // source does without them, e.g. "from the field of view".
  explicit GivenIntrinsics(const std::string& when_not_given);

  // Declares fx, fy, cx, cy, in that order: spec.declare(..., kGivenIntrinsics, ...).
  void declare_in(StageSpec& spec) const;

  // fx, fy, cx, cy as given (width and height 0; all 0 when none is given). Throws
  // facet::StageError when only one of fx and fy is set.
  CameraIntrinsics operator()(const Params& params) const;

 private:
  Param<double> fx_;
  Param<double> fy_;
  Param<double> cx_;
  Param<double> cy_;
};

}  // namespace facet::io
