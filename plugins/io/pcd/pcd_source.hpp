#pragma once
// io.pcd: reads point clouds from PCD files (through PCL's I/O) as depth frames, with the
// cloud's label field as ground truth.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "facet/stage.hpp"
#include "facet/types/frame.hpp"
#include "facet/types/images.hpp"
#include "io/file_playback.hpp"
#include "pcd/cloud_images.hpp"

namespace facet::pcd {

// The PCD files `path` names: a folder (its *.pcd), a glob (wildcards in the file name only) or
// one file; in natural order of their names. Throws facet::StageError when there are none.
std::vector<std::filesystem::path> list_pcd_files(const std::string& path);

class PcdSource final : public Stage {
 public:
  static StageSpec spec();
  explicit PcdSource(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  // Parameters.
  std::string path_;
  std::string intrinsics_param_;
  CameraIntrinsics given_;  // from fx, fy, cx, cy, width, height (zeros when not given)
  LabelScheme scheme_;
  double max_fit_rms_px_;
  io::FilePlayback playback_;

  // Resolved by open().
  std::vector<std::filesystem::path> files_;  // in natural order
  bool have_camera_ = false;                  // false: fit the intrinsics of every frame
  CameraIntrinsics camera_;
};

}  // namespace facet::pcd
