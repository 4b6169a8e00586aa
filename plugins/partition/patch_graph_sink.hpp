#pragma once
// io.patch_graph: writes partition.graph's graph output as <dir>/<stem>.json.

#include <filesystem>

#include "facet/stage.hpp"

namespace facet::partition {

class PatchGraphSink final : public Stage {
 public:
  static StageSpec spec();
  explicit PatchGraphSink(const Params& params);
  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
};

}  // namespace facet::partition
