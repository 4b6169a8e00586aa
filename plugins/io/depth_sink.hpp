#pragma once
// io.depth: writes depth images as 16-bit PNGs in millimetres, the datasets' depth format.

#include <filesystem>

#include "facet/stage.hpp"

namespace facet::io {

class DepthSink final : public Stage {
 public:
  static StageSpec spec();
  explicit DepthSink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
};

}  // namespace facet::io
