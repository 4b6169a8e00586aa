#pragma once
// io.oni: writes a depth stream as an .oni recording (OniDepthWriter), which io.openni2, NiViewer
// and every other OpenNI2 program play back.

#include <cstdint>
#include <filesystem>
#include <memory>

#include "facet/stage.hpp"
#include "facet/types/frame.hpp"
#include "openni2/oni_writer.hpp"

namespace facet::openni2 {

class OniSink final : public Stage {
 public:
  static StageSpec spec();
  explicit OniSink(const Params& params);
  ~OniSink() override;

  void process(ProcessContext& ctx) override;
  void close() override;

 private:
  std::filesystem::path file_;
  int fps_;
  std::unique_ptr<OniDepthWriter> writer_;  // made at the first frame, which fixes size and camera
  std::int64_t last_us_ = -1;
};

// The field of view of a pinhole camera: 2 atan(width / (2 fx)) across, 2 atan(height / (2 fy))
// down (radians); 0 for a camera without focal lengths.
double horizontal_fov_rad(const CameraIntrinsics& camera);
double vertical_fov_rad(const CameraIntrinsics& camera);

}  // namespace facet::openni2
