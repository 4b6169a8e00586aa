#pragma once
// io.depth: writes depth images as 16-bit PNGs in millimetres, the datasets' depth format.

#include <filesystem>

#include "facet/stage.hpp"
#include "io/output_folder.hpp"

namespace facet::io {

class DepthSink final : public Stage {
 public:
  static StageSpec spec();
  explicit DepthSink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
  EarlierResults earlier_;  // what the folder held before this run
};

}  // namespace facet::io
