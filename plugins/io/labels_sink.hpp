#pragma once
// io.labels: writes segment ids as 16-bit PNGs, the format of the datasets' ground truth.

#include <filesystem>

#include "facet/stage.hpp"
#include "io/output_folder.hpp"

namespace facet::io {

class LabelsSink final : public Stage {
 public:
  static StageSpec spec();
  explicit LabelsSink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
  EarlierResults earlier_;  // what the folder held before this run
};

}  // namespace facet::io
