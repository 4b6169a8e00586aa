#pragma once
// io.overlay: a colour PNG per frame for a person to look at: depth as grey, segments blended in
// stable colours, their borders, and optionally the normal edges.

#include <filesystem>

#include "facet/stage.hpp"
#include "io/output_folder.hpp"
#include "io/overlay_render.hpp"

namespace facet::io {

class OverlaySink final : public Stage {
 public:
  static StageSpec spec();
  explicit OverlaySink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
  EarlierResults earlier_;  // what the folder held before this run
  OverlayStyle style_;
};

}  // namespace facet::io
