#include "synthetic/synthetic_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "synthetic/random_stream.hpp"

namespace facet::synthetic {
namespace {

// Purposes of the random streams derived from the seed.
constexpr std::uint64_t kLayoutStream = 1;
constexpr std::uint64_t kNoiseStream = 2;
constexpr std::uint64_t kViewStream = 3;
constexpr int kLayoutAttempts = 60;
// The OpenNI Kinect's focal length at 640 x 480, which the defaults stand for.
constexpr double kKinectFocalPx = 525.0;

std::vector<ParamValue> preset_choices() {
  std::vector<ParamValue> choices;
  for (const std::string& name : preset_names())
    choices.emplace_back(name);
  return choices;
}

// How the layouts of the frames follow each other (param scene).
enum class SceneMode { static_layout, new_layout };
// Where the camera stands (param camera).
enum class CameraMode { fixed, random };

const Out<DepthImage> kDepth{
    "depth",
    "Depth, CV_16UC1 in mm (0 = no measurement), with the frame index, the "
    "stem <preset>_<seed>_<index, 6 digits>, a timestamp of index / fps and "
    "the camera intrinsics."};
const Out<LabelImage> kLabels{
    "labels",
    "Ground truth, CV_32SC1: 1..N the objects, only where they are visible "
    "and measured (depth > 0); 0 table, floor, wall and no measurement. "
    "count = N, the objects of the scene."};
// Text, not an enum: the scene library (layout_scene) and the frame stems go by these names.
const Param<std::string> kPreset{
    "preset",
    "separated3",
    "Scene: separated3 (3 separated objects), touching_pairs (5 objects: two touching "
    "pairs and one alone), stacked_occluded (9 objects: three stacks and an occluding "
    "pair), clutter20 (20 smaller objects close together); hard cases: on_flat (6-15: "
    "books, magazines, trays, tins with 1-3 objects standing on each, a few others), "
    "pile20 (15-25 packed close: touching, stacked, flat, cups, bowls), office (10-16: "
    "books, a magazine, a tin, cereal boxes, bowls, cups, a lying can, small boxes), "
    "containers (6-10: bowls, cups, boxes).",
    {.choices = preset_choices(), .origin = "the levels of the paper's Table II"}};
const Param<std::int64_t> kSeed{
    "seed",
    1,
    "Seed of the layout and the noise; the same seed gives the same frames.",
    {.min = 0.0}};
const Param<std::int64_t> kFrames{"frames",
                                  10,
                                  "Frames to generate before the stream ends; 0 = no end (bound it "
                                  "with facet run --frames).",
                                  {.unit = "frames", .min = 0.0}};
const EnumParam<SceneMode> kScene{
    "scene",
    SceneMode::static_layout,
    {{SceneMode::static_layout, "static"}, {SceneMode::new_layout, "new"}},
    "static: one layout, new noise every frame (stability measurements); new: a new "
    "layout every frame."};
const Param<double> kFps{
    "fps",
    30.0,
    "Nominal frame rate; timestamps are frame index / fps.",
    {.unit = "Hz", .min = 0.001, .max = 10000.0, .origin = "Kinect v1: 30 Hz"}};
const Param<int> kWidth{
    "width",
    640,
    "Image width.",
    {.unit = "px", .min = 8.0, .max = 4096.0, .origin = "Kinect v1 depth: 640 x 480"}};
const Param<int> kHeight{
    "height",
    480,
    "Image height.",
    {.unit = "px", .min = 8.0, .max = 4096.0, .origin = "Kinect v1 depth: 640 x 480"}};
const Param<double> kFocal{
    "focal_px",
    0.0,
    "Focal length of the depth image (fx = fy; cx, cy at the image centre); 0 = 525 * "
    "width / 640.",
    {.unit = "px",
     .min = 0.0,
     .max = 100000.0,
     .origin = "525: the OpenNI Kinect value, as in data/mosd"}};
const EnumParam<CameraMode> kCamera{
    "camera",
    CameraMode::fixed,
    {{CameraMode::fixed, "fixed"}, {CameraMode::random, "random"}},
    "fixed: the camera at camera_distance_m and camera_tilt_deg; random: its height "
    "above the table and its tilt drawn per layout from the seed, uniformly in "
    "[camera_height_min_m, camera_height_max_m] and [camera_tilt_min_deg, "
    "camera_tilt_max_deg]. Either way it looks at the middle of the objects' area."};
const Param<double> kCameraDistance{
    "camera_distance_m",
    0.95,
    "camera fixed: distance from the camera to the table point at the image centre.",
    {.unit = "m", .min = 0.3, .max = 5.0, .origin = "like the mOSD frames"}};
const Param<double> kCameraTilt{
    "camera_tilt_deg",
    50.0,
    "camera fixed: angle of the optical axis below the horizontal.",
    {.unit = "deg", .min = 10.0, .max = 90.0, .origin = "like the mOSD frames"}};
const Param<double> kCameraHeightMin{"camera_height_min_m",
                                     0.6,
                                     "camera random: lowest camera height above the table.",
                                     {.unit = "m", .min = 0.2, .max = 4.0}};
const Param<double> kCameraHeightMax{"camera_height_max_m",
                                     1.8,
                                     "camera random: highest camera height above the table.",
                                     {.unit = "m", .min = 0.2, .max = 4.0}};
const Param<double> kCameraTiltMin{"camera_tilt_min_deg",
                                   30.0,
                                   "camera random: smallest tilt below the horizontal.",
                                   {.unit = "deg", .min = 10.0, .max = 90.0}};
const Param<double> kCameraTiltMax{"camera_tilt_max_deg",
                                   70.0,
                                   "camera random: largest tilt below the horizontal.",
                                   {.unit = "deg", .min = 10.0, .max = 90.0}};
const Param<double> kTableHeight{"table_height_m",
                                 0.72,
                                 "Height of the table top above the floor.",
                                 {.unit = "m", .min = 0.05, .max = 3.0}};
const EnumParam<TableEdge> kTableEdge{
    "table_edge",
    TableEdge::hidden,
    {{TableEdge::hidden, "hidden"}, {TableEdge::in_view, "in_view"}, {TableEdge::random, "random"}},
    "hidden: the table's front edge lies outside the image; in_view: it crosses the "
    "lower part of the image (30 % of the way from the nearest table point in view to "
    "the image centre), so its 3 cm front face and the floor 0.72 m below show; "
    "random: either, drawn per layout (half each)."};
const Param<bool> kWall{
    "wall", false,
    "wall_placement fixed: a wall behind the table (background, label 0), which ends "
    "the table."};
const Param<double> kWallDistance{
    "wall_distance_m",
    0.45,
    "wall_placement fixed: distance of the wall behind the table point at the image "
    "centre (along the view).",
    {.unit = "m", .min = 0.3, .max = 5.0}};
const EnumParam<WallPlacement> kWallPlacement{
    "wall_placement",
    WallPlacement::fixed,
    {{WallPlacement::fixed, "fixed"},
     {WallPlacement::camera, "camera"},
     {WallPlacement::random, "random"}},
    "fixed: the wall of wall and wall_distance_m; camera: a wall wall_camera_distance_m "
    "from the camera (horizontally, along the view), the table ending 0.6 m beyond the "
    "image centre or at the wall; random: per layout, a wall in three layouts of four, "
    "its distance from the camera drawn in [wall_camera_min_m, wall_camera_max_m] and "
    "at least 0.45 m beyond the image centre's table point."};
const Param<double> kWallCameraDistance{
    "wall_camera_distance_m",
    2.5,
    "wall_placement camera: horizontal distance from the camera to the wall.",
    {.unit = "m", .min = 0.3, .max = 20.0}};
const Param<double> kWallCameraMin{"wall_camera_min_m",
                                   1.5,
                                   "wall_placement random: nearest wall from the camera.",
                                   {.unit = "m", .min = 0.3, .max = 20.0}};
const Param<double> kWallCameraMax{"wall_camera_max_m",
                                   4.0,
                                   "wall_placement random: farthest wall from the camera.",
                                   {.unit = "m", .min = 0.3, .max = 20.0}};
const Param<int> kMinVisible{
    "min_visible_px",
    150,
    "Every object shows at least this many pixels to a perfect camera; layouts that "
    "do not are drawn again (with the view drawn again too when camera, table_edge or "
    "wall_placement is random; then only pixels the sensor can measure count: in "
    "[min_depth_m, max_depth_m] and, with shadows, lit by the projector). A pixel count for a "
    "focal length of 525 px (a Kinect at 640 x 480): it scales with the square of the focal "
    "length, as the pixels an object covers do, so that a seed gives the same layouts at any "
    "resolution.",
    {.unit = "px", .min = 1.0}};
const Param<bool> kNoise{
    "noise", true,
    "Kinect v1 effects on; false: the exact depth rounded to mm (range limits apply)."};
const Param<double> kAxialNoiseScale{
    "axial_noise_scale",
    1.0,
    "Factor on the axial noise sigma_z = 0.0012 + 0.0019 (z - 0.4)^2 + 0.0001 / sqrt(z) "
    "theta^2 / (pi/2 - theta)^2 m (z in m, theta the incidence angle); the depth "
    "delivered, quantised, has this sigma.",
    {.min = 0.0, .max = 100.0, .origin = "Nguyen, Izadi, Lovell 2012"}};
const Param<double> kDisparityStep{
    "disparity_step_px",
    0.125,
    "Disparity resolution; depth is ir_focal_px * baseline_m / quantised disparity. "
    "0 = no quantisation.",
    {.unit = "px", .min = 0.0, .max = 10.0, .origin = "Kinect v1: 1/8 px"}};
const Param<double> kIrFocal{
    "ir_focal_px",
    580.0,
    "Focal length of the IR camera that measures the disparity.",
    {.unit = "px", .min = 1.0, .max = 100000.0, .origin = "Kinect v1 literature"}};
const Param<double> kBaseline{
    "baseline_m",
    0.075,
    "Projector offset to the camera's right (+x): shadows fall on the objects' left; "
    "negative = to the left; at least 1 mm either way.",
    {.unit = "m", .min = -1.0, .max = 1.0, .origin = "Kinect v1: 7.5 cm"}};
const Param<bool> kShadows{"shadows", true,
                           "Surfaces the projector does not light get no measurement."};
const Param<double> kJumpDropout{
    "jump_dropout",
    0.5,
    "Chance that a pixel beside a depth jump (4-neighbour farther than jump_min_m + "
    "1 % of the depth) gets no measurement.",
    {.min = 0.0, .max = 1.0}};
const Param<double> kJumpMin{"jump_min_m",
                             0.02,
                             "Smallest depth difference between neighbours that is a jump.",
                             {.unit = "m", .min = 0.0, .max = 10.0}};
const Param<double> kGrazingStart{
    "grazing_start_deg",
    80.0,
    "Incidence angle (camera or projector ray to the surface normal) from which pixels "
    "drop out; the chance grows linearly to 1 at grazing_end_deg.",
    {.unit = "deg", .min = 0.0, .max = 90.0}};
const Param<double> kGrazingEnd{"grazing_end_deg",
                                89.0,
                                "Incidence angle from which no pixel is measured.",
                                {.unit = "deg", .min = 0.0, .max = 90.0}};
const Param<double> kDropoutCell{
    "dropout_cell_px",
    4.0,
    "Dropouts (beside jumps, at grazing angles) come in blobs of about this size: a "
    "pixel drops out where a smooth random field with cells of this size is below its "
    "dropout chance; 1 = independent pixels.",
    {.unit = "px",
     .min = 1.0,
     .max = 100.0,
     .origin = "Kinect v1 disparity is matched over windows of several pixels"}};
const Param<double> kMinDepth{
    "min_depth_m",
    0.5,
    "Nearest measured depth.",
    {.unit = "m", .min = 0.0, .max = 100.0, .origin = "Kinect v1: about 0.5 m"}};
const Param<double> kMaxDepth{
    "max_depth_m",
    4.0,
    "Farthest measured depth.",
    {.unit = "m", .min = 0.01, .max = 65.0, .origin = "Kinect v1: about 4 m"}};

std::string frame_stem(const std::string& preset, std::uint64_t seed, std::int64_t index) {
  char number[24];
  std::snprintf(number, sizeof number, "%06lld", static_cast<long long>(index));
  return preset + "_" + std::to_string(seed) + "_" + number;
}

std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Pixels per label that the sensor can measure at all: in its range and, with shadows on, lit
// by the projector (the dropouts and the noise come on top of this).
std::vector<int> measurable_pixels(const IdealFrame& frame, const Scene& scene,
                                   const CameraRig& rig, const KinectNoise& noise) {
  std::vector<int> counts(static_cast<std::size_t>(scene.object_count) + 1, 0);
  const bool shadows = noise.enabled && noise.shadows;
  for (int v = 0; v < frame.labels.rows; ++v) {
    const auto* labels = frame.labels.ptr<std::int32_t>(v);
    const auto* depth = frame.depth_m.ptr<double>(v);
    const auto* points = frame.points.ptr<cv::Vec3d>(v);
    for (int u = 0; u < frame.labels.cols; ++u) {
      if (labels[u] <= 0 || labels[u] > scene.object_count) continue;
      if (depth[u] < noise.min_depth_m || depth[u] > noise.max_depth_m) continue;
      if (shadows && !lit_by_projector(scene, rig, points[u])) continue;
      ++counts[static_cast<std::size_t>(labels[u])];
    }
  }
  return counts;
}

// min_visible_px at another focal length: an object covers pixels in proportion to its square.
// Exact at the Kinect's, so 640 x 480 layouts are drawn as they always were.
int min_visible_at_focal(int min_visible_px, double focal_px) {
  const double area_factor = (focal_px / kKinectFocalPx) * (focal_px / kKinectFocalPx);
  if (area_factor == 1.0) return min_visible_px;
  return std::max(1, static_cast<int>(std::lround(min_visible_px * area_factor)));
}

}  // namespace

StageSpec SyntheticSource::spec() {
  StageSpec spec(
      "io.synthetic",
      "Generates table-top scenes as a Kinect v1 sees them, with ground-truth labels.\n"
      "Boxes, rounded boxes, cylinders (upright and lying), spheres, flat objects (books, "
      "magazines, trays, tins), open cups and bowls on a table (optionally with its front edge "
      "and the floor in view, and a wall behind it), ray-cast exactly and then measured with a "
      "Kinect v1 noise model: "
      "range limits, projector shadows, dropouts beside depth jumps and at grazing angles, "
      "axial noise growing with the square of the distance and with the incidence angle, and "
      "depth from disparity quantised to 1/8 px (docs/synthetic.md). Presets of increasing "
      "complexity follow the levels of "
      "the paper's Table II; on_flat, pile20, office and containers are hard cases. The camera "
      "pose, the table edge and the wall can be drawn per layout from the seed. A static scene "
      "(the default) is the same layout in every frame with "
      "independent noise, for stability measurements. Everything is deterministic for a seed. "
      "Reports the metrics valid_ratio (measured pixels / all), objects_visible, camera_height_m, "
      "camera_tilt_deg, wall_from_camera_m (0 = no wall) and table_edge_in_view (0 or 1).");
  spec.declare(kDepth, kLabels, kPreset, kSeed, kFrames, kScene, kFps, kWidth, kHeight, kFocal,
               kCamera, kCameraDistance, kCameraTilt, kCameraHeightMin, kCameraHeightMax,
               kCameraTiltMin, kCameraTiltMax, kTableHeight, kTableEdge, kWall, kWallDistance,
               kWallPlacement, kWallCameraDistance, kWallCameraMin, kWallCameraMax, kMinVisible,
               kNoise, kAxialNoiseScale, kDisparityStep, kIrFocal, kBaseline, kShadows,
               kJumpDropout, kJumpMin, kGrazingStart, kGrazingEnd, kDropoutCell, kMinDepth,
               kMaxDepth)
      .concurrency(Concurrency::serial);
  return spec;
}

SyntheticSource::SyntheticSource(const Params& params)
    : preset_(kPreset(params)),
      seed_(static_cast<std::uint64_t>(kSeed(params))),
      frames_(kFrames(params)),
      new_scene_each_frame_(kScene(params) == SceneMode::new_layout),
      fps_hz_(kFps(params)) {
  view_.random_camera = kCamera(params) == CameraMode::random;
  view_.camera_distance_m = kCameraDistance(params);
  view_.camera_tilt_deg = kCameraTilt(params);
  view_.height_min_m = kCameraHeightMin(params);
  view_.height_max_m = kCameraHeightMax(params);
  view_.tilt_min_deg = kCameraTiltMin(params);
  view_.tilt_max_deg = kCameraTiltMax(params);
  view_.projector_offset_m = kBaseline(params);
  view_.table_edge = kTableEdge(params);
  view_.wall = kWallPlacement(params);
  view_.wall_camera_distance_m = kWallCameraDistance(params);
  view_.wall_camera_min_m = kWallCameraMin(params);
  view_.wall_camera_max_m = kWallCameraMax(params);
  view_.room.table_height_m = kTableHeight(params);
  view_.room.wall = kWall(params);
  view_.room.wall_distance_m = kWallDistance(params);

  noise_.enabled = kNoise(params);
  noise_.axial_noise_scale = kAxialNoiseScale(params);
  noise_.disparity_step_px = kDisparityStep(params);
  noise_.ir_focal_px = kIrFocal(params);
  noise_.baseline_m = std::abs(kBaseline(params));
  noise_.shadows = kShadows(params);
  noise_.jump_dropout = kJumpDropout(params);
  noise_.jump_min_m = kJumpMin(params);
  noise_.grazing_start_deg = kGrazingStart(params);
  noise_.grazing_end_deg = kGrazingEnd(params);
  noise_.dropout_cell_px = kDropoutCell(params);
  noise_.min_depth_m = kMinDepth(params);
  noise_.max_depth_m = kMaxDepth(params);

  const int width = kWidth(params);
  const int height = kHeight(params);
  const double focal_px = kFocal(params);
  const double focal = focal_px > 0.0 ? focal_px : kKinectFocalPx * width / 640.0;
  intrinsics_ = {focal, focal, 0.5 * (width - 1), 0.5 * (height - 1), width, height};
  min_visible_px_ = min_visible_at_focal(kMinVisible(params), focal);

  if (noise_.grazing_end_deg < noise_.grazing_start_deg) {
    throw StageError("param grazing_end_deg=" + format_number(noise_.grazing_end_deg) +
                     " is below grazing_start_deg=" + format_number(noise_.grazing_start_deg) +
                     ": the dropout chance must grow with the angle");
  }
  if (noise_.baseline_m < 0.001) {
    throw StageError("param baseline_m=" + format_number(kBaseline(params)) +
                     ": a structured-light camera measures depth by the disparity between camera "
                     "and projector, which needs a baseline of at least 1 mm");
  }
  if (noise_.min_depth_m >= noise_.max_depth_m) {
    throw StageError("param min_depth_m=" + format_number(noise_.min_depth_m) +
                     " must be below max_depth_m=" + format_number(noise_.max_depth_m));
  }
  auto check_range = [](const char* low_name, double low, const char* high_name, double high) {
    if (low > high) {
      throw StageError(std::string("param ") + high_name + "=" + format_number(high) +
                       " is below " + low_name + "=" + format_number(low) +
                       ": the range it is drawn from is empty");
    }
  };
  check_range("camera_height_min_m", view_.height_min_m, "camera_height_max_m", view_.height_max_m);
  check_range("camera_tilt_min_deg", view_.tilt_min_deg, "camera_tilt_max_deg", view_.tilt_max_deg);
  check_range("wall_camera_min_m", view_.wall_camera_min_m, "wall_camera_max_m",
              view_.wall_camera_max_m);
}

SyntheticSource::Rendered SyntheticSource::make_scene(std::uint64_t scene_index) const {
  RandomStream random(mix_seed(seed_, scene_index, kLayoutStream));
  // Its own stream, so that the layouts of a fixed view are those of earlier versions.
  RandomStream view_random(mix_seed(seed_, scene_index, kViewStream));
  // Rays end a little beyond the farthest measured depth: what lies farther is never measured.
  const double max_ray_depth_m = noise_.max_depth_m * 1.01;
  std::string last_problem;
  for (int attempt = 0; attempt < kLayoutAttempts; ++attempt) {
    Rendered rendered;
    rendered.view = make_view(view_, intrinsics_, view_random);
    try {
      rendered.scene = layout_scene(preset_, rendered.view.room, random);
    } catch (const std::runtime_error& error) {
      last_problem = error.what();
      continue;
    }
    rendered.ideal = render_ideal(rendered.scene, rendered.view.rig, max_ray_depth_m);
    // A drawn view may bring the camera nearer than the sensor measures (0.64 m from the
    // look-at point at its lowest and steepest) and hide a small object in a tall one's
    // projector shadow: there only what the sensor can measure counts. The fixed camera keeps
    // the rule of earlier versions, so that its layouts stay the same.
    const std::vector<int> visible =
        view_is_drawn(view_)
            ? measurable_pixels(rendered.ideal, rendered.scene, rendered.view.rig, noise_)
            : visible_pixels(rendered.ideal, rendered.scene.object_count);
    int fewest = visible.size() > 1 ? visible[1] : 0;
    for (std::size_t label = 1; label < visible.size(); ++label)
      fewest = std::min(fewest, visible[label]);
    if (fewest >= min_visible_px_) return rendered;
    last_problem = "an object showed only " + std::to_string(fewest) + " px (min_visible_px " +
                   std::to_string(min_visible_px_) + ")";
  }
  throw StageError("preset '" + preset_ + "', seed " + std::to_string(seed_) + ": no layout in " +
                   std::to_string(kLayoutAttempts) + " attempts shows every object (" +
                   last_problem +
                   "); check camera_distance_m, camera_tilt_deg (or the camera ranges), the "
                   "image size and min_visible_px");
}

void SyntheticSource::open(const OpenContext& /*ctx*/) {
  emitted_ = 0;
  static_scene_.reset();
  if (!new_scene_each_frame_) static_scene_ = make_scene(0);
}

void SyntheticSource::process(ProcessContext& ctx) {
  if (frames_ > 0 && emitted_ >= frames_) {
    ctx.end_of_stream();
    return;
  }
  const std::int64_t index = emitted_;
  std::optional<Rendered> fresh;
  if (new_scene_each_frame_) fresh = make_scene(static_cast<std::uint64_t>(index));
  const Rendered& rendered = new_scene_each_frame_ ? *fresh : *static_scene_;

  RandomStream random(mix_seed(seed_, static_cast<std::uint64_t>(index), kNoiseStream));
  cv::Mat depth_mm =
      measure_depth(rendered.ideal, rendered.scene, rendered.view.rig, noise_, random);

  cv::Mat labels = cv::Mat::zeros(depth_mm.size(), CV_32SC1);
  rendered.ideal.labels.copyTo(labels, depth_mm > 0);

  FrameHeader header;
  header.camera = intrinsics_;
  header.frame.index = index;
  header.frame.stem = frame_stem(preset_, seed_, index);
  header.frame.stream_frames = frames_;  // 0: endless
  header.frame.timestamp_ns =
      static_cast<std::int64_t>(std::llround(static_cast<double>(index) * 1e9 / fps_hz_));

  std::vector<bool> seen(static_cast<std::size_t>(rendered.scene.object_count) + 1, false);
  for (int v = 0; v < labels.rows; ++v) {
    const auto* row = labels.ptr<std::int32_t>(v);
    for (int u = 0; u < labels.cols; ++u)
      seen[static_cast<std::size_t>(row[u])] = true;
  }
  int visible = 0;
  for (std::size_t label = 1; label < seen.size(); ++label)
    visible += seen[label] ? 1 : 0;

  ctx.metric("valid_ratio", static_cast<double>(cv::countNonZero(depth_mm)) /
                                static_cast<double>(depth_mm.total()));
  ctx.metric("objects_visible", visible);
  ctx.metric("camera_height_m", rendered.view.camera_height_m);
  ctx.metric("camera_tilt_deg", rendered.view.camera_tilt_deg);
  ctx.metric("wall_from_camera_m", rendered.view.wall_from_camera_m);
  ctx.metric("table_edge_in_view", rendered.view.table_edge_in_view ? 1 : 0);
  kDepth(ctx, DepthImage::make(header, depth_mm));
  kLabels(ctx, LabelImage::make(header, labels, rendered.scene.object_count));
  ++emitted_;
}

}  // namespace facet::synthetic
