#pragma once
// io.synthetic: table-top scenes rendered as a Kinect v1 would see them, with ground-truth labels.
// Shares no code with the stages it is used to test.

#include <cstdint>
#include <optional>
#include <string>

#include "facet/stage.hpp"
#include "synthetic/kinect_noise.hpp"
#include "synthetic/ray_caster.hpp"
#include "synthetic/scene.hpp"
#include "synthetic/scene_layout.hpp"
#include "synthetic/view_setup.hpp"

namespace facet::synthetic {

class SyntheticSource final : public Stage {
 public:
  static StageSpec spec();
  explicit SyntheticSource(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

  const KinectNoise& noise() const { return noise_; }

 private:
  // A scene of the preset (seeded by seed and `scene_index`) in which every object shows at
  // least min_visible_px pixels; throws StageError when no such layout is found. A drawn view
  // (camera, table edge, wall) is drawn again with the layout.
  struct Rendered {
    View view;
    Scene scene;
    IdealFrame ideal;
  };
  Rendered make_scene(std::uint64_t scene_index) const;

  // Parameters.
  std::string preset_;
  std::uint64_t seed_;
  std::int64_t frames_;
  bool new_scene_each_frame_;
  double fps_hz_;
  ViewOptions view_;
  int min_visible_px_;
  KinectNoise noise_;
  CameraIntrinsics intrinsics_;

  // State.
  std::optional<Rendered> static_scene_;
  std::int64_t emitted_ = 0;
};

}  // namespace facet::synthetic
