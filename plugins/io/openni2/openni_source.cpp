#include "openni2/openni_source.hpp"

#include <OpenNI.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <opencv2/core.hpp>
#include <system_error>
#include <thread>
#include <vector>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "io/given_intrinsics.hpp"
#include "openni2/openni_runtime.hpp"

namespace fs = std::filesystem;

namespace facet::openni2 {
namespace {

const Out<DepthImage> kDepth{"depth",
                             "Depth, CV_16UC1 in mm (0 = invalid), with frame index, device "
                             "timestamp, stem and camera intrinsics."};
const Param<std::string> kUri{
    "uri",
    "",
    "Device URI (as `facet doctor` lists them), path of an .oni recording, or empty "
    "for the first device found.",
    {.origin = "empty: the first device"}};
const Param<int> kWidth{"width",
                        0,
                        "Depth image width of the video mode; 0 = the device's default.",
                        {.unit = "px", .min = 0, .max = 4096}};
const Param<int> kHeight{"height",
                         0,
                         "Depth image height of the video mode; 0 = the device's default.",
                         {.unit = "px", .min = 0, .max = 4096}};
const Param<int> kFps{"fps",
                      0,
                      "Frame rate of the video mode; 0 = the device's default.",
                      {.unit = "Hz", .min = 0, .max = 1000}};
const Param<bool> kRegistration{
    "registration", false,
    "Register depth to the colour camera (the device warps depth into the colour "
    "image; the intrinsics are then the colour camera's). An error when the device "
    "cannot."};
const Param<bool> kMirror{"mirror", false,
                          "Mirror the image left to right (OpenNI2's mirroring; off keeps the "
                          "camera geometry of the intrinsics)."};
const EnumParam<FramePolicyParam> kPolicy{
    "policy",
    FramePolicyParam::automatic,
    {{FramePolicyParam::automatic, "auto"},
     {FramePolicyParam::latest, "latest"},
     {FramePolicyParam::block, "block"}},
    "latest: newest frame, stale ones dropped (live use); block: every frame in order; "
    "auto: latest for devices, block for recordings."};
const Param<int> kTimeoutMs{
    "timeout_ms",
    2000,
    "How long to wait for a frame before the run stops with an error naming the URI.",
    {.unit = "ms", .min = 1, .max = 600000}};
const Param<double> kSpeed{"speed",
                           -1.0,
                           "Recordings only: playback speed as a multiple of the recorded rate; "
                           "-1 = as fast as the graph reads (every frame, no waiting).",
                           {.min = -1.0, .max = 100.0, .origin = "-1: offline processing"}};
const Param<bool> kLoop{
    "loop", false,
    "Recordings only: start again after the last frame instead of ending the stream."};
const io::GivenIntrinsics kGivenIntrinsics{"from the field of view"};

std::string pixel_format_name(openni::PixelFormat format) {
  switch (format) {
    case openni::PIXEL_FORMAT_DEPTH_1_MM:
      return "1 mm";
    case openni::PIXEL_FORMAT_DEPTH_100_UM:
      return "100 um";
    case openni::PIXEL_FORMAT_SHIFT_9_2:
      return "shift 9.2";
    case openni::PIXEL_FORMAT_SHIFT_9_3:
      return "shift 9.3";
    default:
      return "pixel format " + std::to_string(static_cast<int>(format));
  }
}

DepthMode to_depth_mode(const openni::VideoMode& mode) {
  return {mode.getResolutionX(), mode.getResolutionY(), mode.getFps(),
          pixel_format_name(mode.getPixelFormat()),
          mode.getPixelFormat() == openni::PIXEL_FORMAT_DEPTH_1_MM};
}

openni::VideoMode to_video_mode(const DepthMode& mode) {
  openni::VideoMode video;
  video.setResolution(mode.width_px, mode.height_px);
  video.setFps(mode.fps);
  video.setPixelFormat(openni::PIXEL_FORMAT_DEPTH_1_MM);
  return video;
}

bool ends_with_oni(const std::string& uri) {
  if (uri.size() < 4) return false;
  std::string ext = uri.substr(uri.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".oni";
}

std::string frame_stem(std::int64_t index) {
  char stem[32];
  std::snprintf(stem, sizeof(stem), "frame_%06lld", static_cast<long long>(index));
  return stem;
}

constexpr std::chrono::milliseconds kStopGrace{100};
// How long a recording that is closed unread waits for its player thread's first frame.
constexpr int kPlayerStartTimeout_ms = 2000;

FramePolicy policy_for(FramePolicyParam param, bool recording) {
  switch (param) {
    case FramePolicyParam::latest:
      return FramePolicy::latest;
    case FramePolicyParam::block:
      return FramePolicy::block;
    case FramePolicyParam::automatic:
      break;
  }
  return recording ? FramePolicy::block : FramePolicy::latest;
}

}  // namespace

bool names_a_recording(const std::string& uri) {
  if (uri.empty()) return false;
  std::error_code error;
  return ends_with_oni(uri) || fs::is_regular_file(uri, error);
}

// Declared in this order so that the stream goes before the device, and both before OpenNI2.
struct OpenNi2Source::Session {
  std::shared_ptr<const OpenNiRuntime> runtime;
  openni::Device device;
  openni::VideoStream stream;
  bool started = false;
  bool live = false;             // a device, not a recording
  bool delivered_frame = false;  // a frame was read, so the player thread of a recording runs

  ~Session() {
    if (!live && device.isValid() && !delivered_frame) let_the_player_thread_start();
    if (stream.isValid()) {
      if (started) {
        stream.stop();
        // Some drivers return from stop() while their frame thread still finishes its current
        // period (OpenNI2's own test driver, DummyDevice, never joins it); destroying the stream
        // or unloading the driver under that thread crashes the process. A device is given
        // 100 ms (three frame periods at 30 Hz) to let go; recordings' player joins its thread.
        if (live) std::this_thread::sleep_for(kStopGrace);
      }
      stream.destroy();
    }
    if (device.isValid()) device.close();
  }

  // OpenNI2's file player marks itself running only once its thread is first scheduled, so a
  // close() that comes before that is undone: the player thread spins on, close() cancels it
  // after 3 s, and the driver is unloaded under the cancelled thread, which crashes the process.
  // Closing a recording right after opening it (a refused video mode, a graph that stops before
  // its first frame) on a loaded machine does that. A frame comes only from a running player
  // thread, so one is waited for before closing.
  void let_the_player_thread_start() {
    if (!stream.isValid()) {
      std::this_thread::sleep_for(kStopGrace);  // no stream to wait on: give the thread time
      return;
    }
    if (!started) {
      if (stream.start() != openni::STATUS_OK) return;
      started = true;
    }
    openni::VideoStream* streams[] = {&stream};
    int ready = -1;
    if (openni::OpenNI::waitForAnyStream(streams, 1, &ready, kPlayerStartTimeout_ms) ==
        openni::STATUS_OK) {
      openni::VideoFrameRef frame;
      stream.readFrame(&frame);
    }
  }
};

StageSpec OpenNi2Source::spec() {
  StageSpec spec(
      "io.openni2",
      "Depth frames from an OpenNI2 device or an .oni recording (see docs/cameras.md).\n"
      "'uri' is empty (the first device OpenNI2 finds), a device URI as `facet doctor` lists "
      "it, or the path of an .oni file, which OpenNI2's file driver plays. Depth is CV_16UC1 "
      "in mm (the device's 1 mm depth mode; 0 = no measurement). Every frame carries its "
      "index in this stream, the device's timestamp (microseconds, converted to ns), the "
      "stem frame_NNNNNN and pinhole intrinsics from the stream's field of view (or fx, fy, "
      "cx, cy when given). policy 'latest' (live) passes on the newest frame and drops the "
      "ones that queued up while the graph was busy; 'block' passes on every frame. Frames "
      "the device numbered but this source never passed on are reported as the metric "
      "dropped_frames and in a warning at most every 300 frames. A recording ends the "
      "stream after its last frame unless 'loop' is set. Errors name the URI and quote "
      "OpenNI2.");
  return spec
      .declare(kDepth, kUri, kWidth, kHeight, kFps, kRegistration, kMirror, kPolicy, kTimeoutMs,
               kSpeed, kLoop, kGivenIntrinsics)
      .concurrency(Concurrency::serial);
}

OpenNi2Source::OpenNi2Source(const Params& params)
    : uri_(kUri(params)),
      registration_(kRegistration(params)),
      mirror_(kMirror(params)),
      policy_param_(kPolicy(params)),
      timeout_ms_(kTimeoutMs(params)),
      speed_(kSpeed(params)),
      loop_(kLoop(params)),
      given_(kGivenIntrinsics(params)) {
  request_.width_px = kWidth(params);
  request_.height_px = kHeight(params);
  request_.fps = kFps(params);
  if (speed_ != -1.0 && !(speed_ > 0.0)) {
    throw StageError("param 'speed' is " + std::to_string(speed_) +
                     ": give -1 (as fast as possible) or a multiple of the recorded rate > 0");
  }
}

OpenNi2Source::~OpenNi2Source() = default;

std::string OpenNi2Source::what() const {
  if (uri_.empty()) return "the first OpenNI2 device (uri \"\")";
  return (recording_ ? "recording '" : "OpenNI2 device '") + uri_ + "'";
}

void OpenNi2Source::open(const OpenContext& /*ctx*/) {
  recording_ = names_a_recording(uri_);
  policy_ = policy_for(policy_param_, recording_);
  last_file_frame_ = 0;
  file_finished_ = false;
  drops_ = FrameDrops();
  if (recording_) {
    std::error_code error;
    if (!fs::exists(uri_, error)) {
      throw StageError("recording '" + uri_ + "' does not exist (param 'uri': an .oni file, a " +
                       "device URI, or empty for the first device)");
    }
    if (!fs::is_regular_file(uri_, error)) {
      throw StageError("recording '" + uri_ + "' is not a file");
    }
  }
  start_session();
}

void OpenNi2Source::start_session() {
  auto session = std::make_unique<Session>();
  session->runtime = OpenNiRuntime::acquire();
  session->live = !recording_;
  openni::Device& device = session->device;
  if (device.open(uri_.empty() ? openni::ANY_DEVICE : uri_.c_str()) != openni::STATUS_OK) {
    const std::string reason = openni_last_error();
    if (recording_) {
      throw StageError("cannot play recording '" + uri_ + "': OpenNI2 says: " + reason +
                       " (is it an .oni recording?)");
    }
    if (uri_.empty()) {
      throw StageError("no OpenNI2 device to open (uri \"\" = the first device): OpenNI2 says: " +
                       reason + "; `facet doctor` lists the drivers and devices OpenNI2 finds");
    }
    throw StageError("cannot open OpenNI2 device '" + uri_ + "': OpenNI2 says: " + reason +
                     " (unplugged, or busy in another program? `facet doctor` lists the devices)");
  }
  const openni::SensorInfo* depth_sensor = device.getSensorInfo(openni::SENSOR_DEPTH);
  if (depth_sensor == nullptr) throw StageError(what() + " has no depth sensor");
  openni::VideoStream& stream = session->stream;
  if (stream.create(device, openni::SENSOR_DEPTH) != openni::STATUS_OK) {
    throw StageError("cannot create the depth stream of " + what() +
                     ": OpenNI2 says: " + openni_last_error());
  }

  std::vector<DepthMode> supported;
  const auto& modes = depth_sensor->getSupportedVideoModes();
  for (int i = 0; i < modes.getSize(); ++i)
    supported.push_back(to_depth_mode(modes[i]));
  const DepthMode current = to_depth_mode(stream.getVideoMode());
  if (recording_) {
    // A recording's mode is what was recorded; a request can only be checked against it.
    if (!current.millimetres) {
      throw StageError(what() + " holds depth as " + current.pixel_format +
                       "; io.openni2 reads 1 mm depth only");
    }
    mode_ = choose_depth_mode({current}, current, request_, uri_);
  } else {
    mode_ = choose_depth_mode(supported, current, request_, uri_.empty() ? "(first device)" : uri_);
    if (!(mode_ == current) && stream.setVideoMode(to_video_mode(mode_)) != openni::STATUS_OK) {
      throw StageError("cannot set depth mode " + describe(mode_) + " on " + what() +
                       ": OpenNI2 says: " + openni_last_error());
    }
  }

  if (stream.isPropertySupported(openni::STREAM_PROPERTY_MIRRORING)) {
    if (stream.setMirroringEnabled(mirror_) != openni::STATUS_OK && mirror_) {
      throw StageError("cannot mirror " + what() + ": OpenNI2 says: " + openni_last_error());
    }
  } else if (mirror_) {
    throw StageError(what() + " does not support mirroring (param 'mirror')");
  }

  double hfov_rad = stream.getHorizontalFieldOfView();
  double vfov_rad = stream.getVerticalFieldOfView();
  if (registration_) {
    if (!device.isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR)) {
      throw StageError(what() + " cannot register depth to colour (param 'registration')");
    }
    if (device.setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR) !=
        openni::STATUS_OK) {
      throw StageError("cannot register depth to colour on " + what() +
                       ": OpenNI2 says: " + openni_last_error());
    }
    // Registered depth is in the colour camera's geometry: take that camera's field of view.
    openni::VideoStream colour;
    if (device.hasSensor(openni::SENSOR_COLOR) &&
        colour.create(device, openni::SENSOR_COLOR) == openni::STATUS_OK) {
      hfov_rad = colour.getHorizontalFieldOfView();
      vfov_rad = colour.getVerticalFieldOfView();
      colour.destroy();
    }
  }

  if (recording_) {
    openni::PlaybackControl* playback = device.getPlaybackControl();
    if (playback == nullptr) throw StageError(what() + ": OpenNI2 gives no playback control");
    // The player always repeats, and io.openni2 ends the stream itself after the file's last
    // frame (its frame numbers run 1..N): OpenNI2's own end-of-file path loses a device record
    // in the player thread, a leak every run would report under a leak checker.
    playback->setRepeatEnabled(true);
    if (playback->setSpeed(static_cast<float>(speed_)) != openni::STATUS_OK) {
      throw StageError("cannot set playback speed " + std::to_string(speed_) + " on " + what() +
                       ": OpenNI2 says: " + openni_last_error());
    }
    frames_in_recording_ = std::max(0, playback->getNumberOfFrames(stream));
  }
  if (given_.fx > 0.0) {
    camera_ = given_;
    camera_.width = mode_.width_px;
    camera_.height = mode_.height_px;
  } else {
    camera_ = intrinsics_from_fov(mode_.width_px, mode_.height_px, hfov_rad, vfov_rad);
    if (!camera_.valid()) {
      throw StageError(what() + " reports no field of view (" + std::to_string(hfov_rad) + " x " +
                       std::to_string(vfov_rad) + " rad): give fx, fy, cx, cy");
    }
  }
  if (stream.start() != openni::STATUS_OK) {
    throw StageError("cannot start the depth stream of " + what() +
                     ": OpenNI2 says: " + openni_last_error());
  }
  session->started = true;
  session_ = std::move(session);
}

void OpenNi2Source::process(ProcessContext& ctx) {
  if (!session_) throw StageError("io.openni2: process() before open()");
  if (file_finished_) {
    ctx.end_of_stream();
    return;
  }
  openni::VideoStream* streams[] = {&session_->stream};
  int ready = -1;
  const openni::Status waited = openni::OpenNI::waitForAnyStream(streams, 1, &ready, timeout_ms_);
  if (waited == openni::STATUS_TIME_OUT) {
    // A recording that stops delivering has ended (its frame count may be unknown).
    if (recording_ && !loop_ && last_file_frame_ > 0) {
      ctx.end_of_stream();
      return;
    }
    throw StageError("no frame from " + what() + " within " + std::to_string(timeout_ms_) +
                     " ms (param 'timeout_ms'): OpenNI2 says: " + openni_last_error());
  }
  if (waited != openni::STATUS_OK) {
    throw StageError("waiting for a frame from " + what() +
                     " failed: OpenNI2 says: " + openni_last_error());
  }
  openni::VideoFrameRef frame;
  if (session_->stream.readFrame(&frame) != openni::STATUS_OK) {
    throw StageError("cannot read a frame from " + what() +
                     ": OpenNI2 says: " + openni_last_error());
  }
  session_->delivered_frame = true;
  if (policy_ == FramePolicy::latest) {
    // Drain what queued up while the graph worked on the previous frame; keep the newest.
    openni::VideoFrameRef newer;
    while (openni::OpenNI::waitForAnyStream(streams, 1, &ready, 0) == openni::STATUS_OK &&
           session_->stream.readFrame(&newer) == openni::STATUS_OK) {
      frame = newer;
    }
  }
  if (recording_ && !loop_) {
    const std::int64_t number = frame.getFrameIndex();
    if (last_file_frame_ > 0 && number <= last_file_frame_) {
      ctx.end_of_stream();  // the player started the file again: the recording has ended
      return;
    }
    last_file_frame_ = number;
    file_finished_ = frames_in_recording_ > 0 && number >= frames_in_recording_;
  }

  if (frame.getVideoMode().getPixelFormat() != openni::PIXEL_FORMAT_DEPTH_1_MM) {
    throw StageError(what() + " delivered a frame as " +
                     pixel_format_name(frame.getVideoMode().getPixelFormat()) +
                     " instead of 1 mm depth");
  }
  const cv::Mat view(frame.getHeight(), frame.getWidth(), CV_16UC1,
                     const_cast<void*>(frame.getData()),
                     static_cast<std::size_t>(frame.getStrideInBytes()));

  FrameHeader header;
  header.frame.index = ctx.frame_index();
  header.frame.timestamp_ns = static_cast<std::int64_t>(frame.getTimestamp()) * 1000;
  header.frame.stem = frame_stem(header.frame.index);
  header.camera = camera_;
  header.camera.width = frame.getWidth();
  header.camera.height = frame.getHeight();
  // A copy: the frame's buffer goes back to OpenNI2 with `frame`.
  DepthImage depth = DepthImage::make(header, view.clone());

  ctx.metric("dropped_frames", static_cast<double>(drops_.passed_on(frame.getFrameIndex())));
  if (auto warning = drops_.warning()) ctx.warn(what() + ": " + *warning);
  kDepth(ctx, std::move(depth));
}

void OpenNi2Source::close() {
  session_.reset();
}

}  // namespace facet::openni2
