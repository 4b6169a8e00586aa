#pragma once
// io.openni2: depth frames from an OpenNI2 device (Kinect, Asus Xtion, PrimeSense Carmine,
// Orbbec Astra, with their drivers) or from an .oni recording played by OpenNI2.

#include <cstdint>
#include <memory>
#include <string>

#include "facet/stage.hpp"
#include "facet/types/frame.hpp"
#include "openni2/depth_modes.hpp"
#include "openni2/frame_drops.hpp"

namespace facet::openni2 {

// How frames are taken from the stream. `latest`: every process() call passes on the newest
// frame and drops the ones that queued up meanwhile (a live camera: the graph sees the present).
// `block`: every frame in order (a recording: nothing is lost).
enum class FramePolicy { latest, block };
// The `policy` parameter: one of the policies, or `automatic` (latest for a device, block for a
// recording).
enum class FramePolicyParam { automatic, latest, block };

// Whether `uri` names a recording rather than a device: an existing regular file, or a name
// ending in ".oni" (any case). OpenNI2 device URIs ("1d27/0601@2/5") are never files.
bool names_a_recording(const std::string& uri);

class OpenNi2Source final : public Stage {
 public:
  static StageSpec spec();
  explicit OpenNi2Source(const Params& params);
  ~OpenNi2Source() override;

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;
  void close() override;

 private:
  struct Session;  // OpenNI2's device and stream, kept out of this header

  // "device '1d27/0601@2/5'", "the first OpenNI2 device (uri \"\")", "recording 'a.oni'"
  std::string what() const;
  void start_session();

  // Parameters.
  std::string uri_;
  ModeRequest request_;
  bool registration_;
  bool mirror_;
  FramePolicyParam policy_param_;
  int timeout_ms_;
  double speed_;
  bool loop_;
  CameraIntrinsics given_;  // fx, fy, cx, cy (0 = from the field of view)

  // Resolved by open().
  bool recording_ = false;
  FramePolicy policy_ = FramePolicy::latest;
  CameraIntrinsics camera_;
  DepthMode mode_;
  std::int64_t frames_in_recording_ = 0;  // 0 = unknown, or a device
  std::int64_t last_file_frame_ = 0;      // the recording's number of the last frame passed on
  bool file_finished_ = false;            // the recording's last frame was passed on
  FrameDrops drops_;
  std::unique_ptr<Session> session_;
};

}  // namespace facet::openni2
