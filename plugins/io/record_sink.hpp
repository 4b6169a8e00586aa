#pragma once
// io.record: writes a depth stream, with its ground truth when there is one, in the dataset
// layout that io.frames reads, so that a live camera stream can be replayed exactly.

#include <filesystem>
#include <optional>

#include "facet/stage.hpp"
#include "facet/types/frame.hpp"
#include "io/output_folder.hpp"

namespace facet::io {

class RecordSink final : public Stage {
 public:
  static StageSpec spec();
  explicit RecordSink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
  EarlierResults earlier_;                  // what the folder held before this run
  std::optional<CameraIntrinsics> camera_;  // of the first frame, written to intrinsics.yaml
  bool label_folder_ready_ = false;
};

}  // namespace facet::io
