#pragma once
// planes.support: support and background planes (table, floor, walls) found from large surface
// patches (paper sec. II-B d), and the patches left over for objects.

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "facet/algo/label_pieces.hpp"
#include "facet/algo/neighbour_gate.hpp"
#include "facet/stage.hpp"
#include "planes/plane_fit.hpp"
#include "planes/scene_model.hpp"
#include "planes/support_rule.hpp"

namespace facet::planes {

class SupportPlaneStage final : public Stage {
 public:
  static StageSpec spec();
  explicit SupportPlaneStage(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  PlaneFitRule fit_rule_;
  SupportRule support_rule_;
  TableRule table_rule_;
  std::int64_t candidate_min_px_;
  int max_candidates_;
  int planes_per_patch_;
  std::int64_t max_fit_points_;
  double object_face_off_plane_fraction_;
  float min_object_height_m_;
  double horizontal_max_deg_;
  double up_prior_max_deg_;
  std::optional<Eigen::Vector3f> up_;  // nothing = auto
  std::int64_t min_segment_px_;
  algo::NeighbourGate split_gate_;
  algo::LabelPieces pieces_;  // its buffers are kept from frame to frame
  std::uint32_t seed_;
};

}  // namespace facet::planes
