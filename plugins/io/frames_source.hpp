#pragma once
// io.frames: reads recorded depth frames (and ground-truth labels, when present) from disk.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "facet/stage.hpp"
#include "facet/types/frame.hpp"
#include "facet/types/images.hpp"
#include "io/file_playback.hpp"
#include "io/frame_listing.hpp"

namespace facet::io {

class FramesSource final : public Stage {
 public:
  static StageSpec spec();
  explicit FramesSource(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

  // After open(): the frames that will be read, in order (start and stride applied).
  const std::vector<std::filesystem::path>& scheduled_files() const { return schedule_; }
  const CameraIntrinsics& camera() const { return camera_; }

 private:
  // Reads frame `index` of the listing; throws StageError naming the file when it is unusable.
  void read_frame(std::size_t index, cv::Mat& depth, cv::Mat& labels) const;

  // Parameters.
  std::string path_;
  std::string intrinsics_param_;
  std::string labels_dir_param_;
  double depth_scale_;  // depth PNG units per metre; 0 = the layout's convention
  FilePlayback playback_;

  // Resolved by open().
  CameraIntrinsics camera_;
  FrameListing listing_;
  std::vector<std::filesystem::path> schedule_;  // the depth files playback_ scheduled
  std::filesystem::path labels_dir_;             // empty when the dataset has no such folder
};

}  // namespace facet::io
