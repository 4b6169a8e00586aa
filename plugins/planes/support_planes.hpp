#pragma once
// planes.support: support and background planes (table, floor, walls) found from large surface
// patches (paper sec. II-B d), and the patches left over for objects.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "facet/algo/label_pieces.hpp"
#include "facet/algo/neighbour_gate.hpp"
#include "facet/algo/plane.hpp"
#include "facet/stage.hpp"
#include "planes/candidate_planes.hpp"
#include "planes/flat_objects.hpp"
#include "planes/plane_assignment.hpp"
#include "planes/scene_model.hpp"
#include "planes/support_rule.hpp"

namespace facet::planes {

class SupportPlaneStage final : public Stage {
 public:
  static StageSpec spec();
  explicit SupportPlaneStage(const Params& params);
  void process(ProcessContext& ctx) override;

 private:
  std::int32_t split_and_drop_left_patches(cv::Mat& left_labels, std::int32_t patch_count,
                                           const PlaneAssignment& assignment, const cv::Mat& xyz,
                                           std::int64_t min_segment_px,
                                           std::vector<char>& cut_pieces);

  // The four kernels: candidate planes, the table (scene model), the support decision, and the
  // assignment of the points to the accepted planes.
  CandidateRule candidate_rule_;
  algo::RansacPlaneRule fit_rule_;
  TableRule table_rule_;
  SupportRule support_rule_;
  AssignmentRule assignment_rule_;
  FlatObjectRule flat_object_rule_;
  FlatObjectBuffers flat_object_buffers_;
  std::vector<char> cut_pieces_;  // per patch id left: a piece of a patch a plane cut
  double horizontal_max_deg_;
  double up_prior_max_deg_;
  std::optional<Eigen::Vector3f> up_;  // nothing = auto
  std::int64_t min_segment_px_;
  // The pixel counts and widths above are given for this image area (facet/algo/pixel_scale.hpp).
  std::int64_t reference_area_px_;
  algo::NeighbourGate split_gate_;
  algo::LabelPieces pieces_;  // its buffers are kept from frame to frame
  std::uint32_t seed_;
};

}  // namespace facet::planes
