#pragma once
// io.frames: reads recorded depth frames (and ground-truth labels, when present) from disk.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "facet/stage.hpp"
#include "facet/types/frame.hpp"
#include "facet/types/images.hpp"
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
  enum class OnError { fail, skip };

  // Reads frame `index` of the listing; throws StageError naming the file when it is unusable.
  void read_frame(std::size_t index, DepthImage& depth, LabelImage& labels) const;

  // Parameters.
  std::string path_;
  std::string intrinsics_param_;
  std::string labels_dir_param_;
  OnError on_error_;
  std::int64_t start_;
  std::int64_t stride_;
  bool loop_;
  double fps_hz_;
  double depth_scale_;  // depth PNG units per metre; 0 = the layout's convention

  // Resolved by open().
  CameraIntrinsics camera_;
  FrameListing listing_;
  std::vector<std::filesystem::path> schedule_;
  std::vector<std::size_t> schedule_index_;  // per scheduled frame: its index in listing_
  std::filesystem::path labels_dir_;         // empty when the dataset has no such folder

  // Stream position.
  std::size_t next_ = 0;
  std::int64_t emitted_ = 0;
  std::int64_t emitted_in_pass_ = 0;
};

}  // namespace facet::io
