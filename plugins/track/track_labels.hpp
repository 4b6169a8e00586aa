#pragma once
// track.labels: segment ids that stay the same from frame to frame (see label_tracker.hpp).

#include "facet/stage.hpp"
#include "track/label_tracker.hpp"

namespace facet::track {

class TrackLabels final : public Stage {
 public:
  static StageSpec spec();
  explicit TrackLabels(const Params& params);

  void process(ProcessContext& ctx) override;

 private:
  LabelTracker tracker_;
};

}  // namespace facet::track
