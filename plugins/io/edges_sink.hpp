#pragma once
// io.edges: writes edge maps as 8-bit PNGs, the binary decision or the score, for a person to look
// at and for side-by-side comparisons of edge detectors (the paper's Fig. 6).

#include <filesystem>

#include "facet/stage.hpp"
#include "io/output_folder.hpp"

namespace facet::io {

// Which of the edge images io.edges writes.
enum class EdgeOutput { mask, score };

class EdgesSink final : public Stage {
 public:
  static StageSpec spec();
  explicit EdgesSink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
  EarlierResults earlier_;  // what the folder held before this run
  bool write_score_;
};

}  // namespace facet::io
