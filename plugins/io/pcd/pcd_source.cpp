#include "pcd/pcd_source.hpp"

#include <algorithm>
#include <cctype>
#include <opencv2/core.hpp>
#include <system_error>

#include "facet/contract.hpp"
#include "io/file_playback.hpp"
#include "io/frame_listing.hpp"
#include "io/given_intrinsics.hpp"
#include "io/intrinsics_file.hpp"
#include "io/natural_order.hpp"
#include "pcd/pcd_file.hpp"

namespace fs = std::filesystem;

namespace facet::pcd {
namespace {

const Out<DepthImage> kDepth{"depth",
                             "Depth, CV_16UC1 in mm (0 = invalid), with the frame index, "
                             "file stem, timestamp and camera intrinsics."};
const Out<LabelImage> kLabels{
    "labels",
    "Ground-truth segment ids from the 'label' field, CV_32SC1 "
    "(0 = background, and wherever depth is invalid); an empty packet for "
    "clouds without a label field."};
const Param<std::string> kPath{
    "path",
    "",
    "Folder of .pcd files, a glob (wildcards * and ? in the file name) or "
    "one .pcd file.",
    {.required = true}};
const Param<std::string> kIntrinsics{
    "intrinsics",
    "",
    "Intrinsics file (keys fx, fy, cx, cy, width, height); empty = use fx, fy, cx, cy, "
    "or fit the intrinsics from each organized cloud when those are 0.",
    {.origin = "dataset format, see docs/data-formats.md"}};
const io::GivenIntrinsics kGivenIntrinsics{"not given"};
const Param<int> kWidth{
    "width",
    0,
    "Image width for re-projecting unorganized clouds (with fx, fy, cx, cy); 0 = the "
    "organized cloud's width.",
    {.unit = "px", .min = 0.0}};
const Param<int> kHeight{
    "height",
    0,
    "Image height for re-projecting unorganized clouds (with fx, fy, cx, cy); 0 = the "
    "organized cloud's height.",
    {.unit = "px", .min = 0.0}};
const Param<double> kMaxFitRms{
    "max_fit_rms_px",
    1.0,
    "Largest RMS error of the fitted intrinsics: a cloud whose points do not project "
    "onto its WIDTH x HEIGHT grid within it (a cloud reshaped, say 320x960 for "
    "640x480, or not from one pinhole camera) is refused rather than read into a "
    "scrambled depth image. Only used when the intrinsics are fitted.",
    {.unit = "px",
     .min = 0.0,
     .origin = "clouds written from a depth camera fit to about 0.001 px (float "
               "rounding); a reshaped mOSD cloud fits to tens of pixels"}};
const EnumParam<LabelScheme> kLabelScheme{
    "labels",
    LabelScheme::raw,
    {{LabelScheme::raw, "raw"},
     {LabelScheme::mosd, "mosd"},
     {LabelScheme::mosd_parts, "mosd_parts"}},
    "How label values become segment ids: raw keeps them; mosd reads the mOSD scheme "
    "(0-9 = invalid and table, 10k..10k+9 = parts of object k-1) as one id per object; "
    "mosd_parts gives every mOSD part (value >= 20) its own id.",
    {.origin = "raw: the file's own ids"}};
const io::FilePlaybackParams kPlayback{{.item = "file",
                                        .unusable = "unreadable, no x/y/z, intrinsics not fittable",
                                        .timestamp_note = "PCD files carry no time stamp"}};

bool has_pcd_extension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".pcd";
}

template <class Keep>
std::vector<fs::path> files_in(const fs::path& folder, Keep keep) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (entry.is_regular_file(error) && keep(entry.path())) files.push_back(entry.path());
  }
  if (error) throw StageError("cannot list folder '" + folder.string() + "': " + error.message());
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return io::natural_less(a.filename().string(), b.filename().string());
  });
  return files;
}

}  // namespace

std::vector<fs::path> list_pcd_files(const std::string& path) {
  if (path.empty()) throw StageError("param 'path' is empty: set a folder of .pcd files");
  std::error_code error;
  if (io::is_glob(path)) {
    const fs::path pattern(path);
    const fs::path folder = pattern.has_parent_path() ? pattern.parent_path() : fs::path(".");
    if (io::is_glob(folder.string())) {
      throw StageError("path '" + path +
                       "': wildcards are supported in the file name only, not in folders");
    }
    if (!fs::is_directory(folder, error)) {
      throw StageError("path '" + path + "': folder '" + folder.string() + "' does not exist");
    }
    const std::string name_pattern = pattern.filename().string();
    auto files = files_in(folder, [&](const fs::path& file) {
      return io::wildcard_match(name_pattern, file.filename().string());
    });
    if (files.empty()) throw StageError("path '" + path + "' matches no files");
    return files;
  }
  if (fs::is_regular_file(path, error)) return {fs::path(path)};
  if (!fs::is_directory(path, error)) {
    throw StageError("path '" + path +
                     "' does not exist (give a folder of .pcd files, a glob "
                     "such as 'clouds/*.pcd' or one .pcd file)");
  }
  auto files = files_in(path, has_pcd_extension);
  if (files.empty()) throw StageError("no frames: folder '" + path + "' holds no .pcd files");
  return files;
}

StageSpec PcdSource::spec() {
  StageSpec spec(
      "io.pcd",
      "Reads point clouds from PCD files (PCL's format) as depth frames and ground-truth "
      "labels.\n"
      "'path' is a folder of *.pcd files (read in natural order of their names: learn2 "
      "before learn10), a glob such as DIR/learn*.pcd, or one file. Every encoding PCL "
      "reads is accepted (ascii, binary, binary_compressed); the fields x, y, z (metres, "
      "camera frame, z forward) are required, a 'label' field becomes the labels output. "
      "Depth = round(z * 1000) mm; NaN, infinite and non-positive z are invalid (0). A "
      "cloud whose points all have z < 0 is taken as stored with y and z negated and is "
      "flipped back (with a warning). An organized cloud (height > 1) gives pixel (u, v) "
      "the point v * width + u. Intrinsics: from 'intrinsics' or fx, fy, cx, cy when "
      "given, otherwise fitted per frame by least squares of u = fx * x / z + cx and "
      "v = fy * y / z + cy over the valid points (metric fit_rms_px). An unorganized "
      "cloud (height 1) is re-projected with the given intrinsics (the nearest point wins "
      "a pixel) and refused without them. Ends the stream after the last file unless "
      "'loop' is set. Reports the metric valid_ratio (valid pixels / all).");
  return spec
      .declare(kDepth, kLabels, kPath, kIntrinsics, kGivenIntrinsics, kWidth, kHeight, kMaxFitRms,
               kLabelScheme, kPlayback)
      .concurrency(Concurrency::serial);
}

PcdSource::PcdSource(const Params& params)
    : path_(kPath(params)),
      intrinsics_param_(kIntrinsics(params)),
      scheme_(kLabelScheme(params)),
      max_fit_rms_px_(kMaxFitRms(params)),
      playback_(kPlayback(params)) {
  given_ = kGivenIntrinsics(params);
  given_.width = kWidth(params);
  given_.height = kHeight(params);
}

void PcdSource::open(const OpenContext& /*ctx*/) {
  files_ = list_pcd_files(path_);
  const bool focal_given = given_.fx > 0.0 || given_.fy > 0.0;
  if (!intrinsics_param_.empty() && focal_given) {
    throw StageError("set either param 'intrinsics' or params fx, fy, cx, cy, not both");
  }
  have_camera_ = !intrinsics_param_.empty() || focal_given;
  camera_ = intrinsics_param_.empty() ? given_ : io::read_intrinsics(intrinsics_param_);

  playback_.schedule(files_.size(), path_, "files");
}

void PcdSource::process(ProcessContext& ctx) {
  while (true) {
    const std::optional<std::size_t> next = playback_.next();
    if (!next) {
      ctx.end_of_stream();
      return;
    }
    const fs::path& file = files_[*next];
    std::string what = "'";  // (built by appending: GCC 12 warns about "'" + string)
    what += file.string();
    what += '\'';

    CameraIntrinsics camera;
    CloudImages images;
    try {
      CloudPoints cloud = read_pcd(file);
      if (flip_if_behind_camera(cloud)) {
        ctx.warn(what + ": every point has z < 0; read as stored with y and z negated");
      }
      if (cloud.organized()) {
        if (have_camera_) {
          camera = camera_;
          if ((camera.width > 0 && camera.width != cloud.width) ||
              (camera.height > 0 && camera.height != cloud.height)) {
            throw StageError(what + " is an organized " + std::to_string(cloud.width) + "x" +
                             std::to_string(cloud.height) + " cloud, but the intrinsics are for " +
                             std::to_string(camera.width) + "x" + std::to_string(camera.height));
          }
          camera.width = cloud.width;
          camera.height = cloud.height;
        } else {
          const IntrinsicsFit fit = fit_intrinsics(cloud, what);
          camera = fit.camera;
          ctx.metric("fit_rms_px", fit.rms_px);
          if (!(fit.rms_px <= max_fit_rms_px_)) {
            throw StageError(what + ": its points do not project onto its " +
                             std::to_string(cloud.width) + "x" + std::to_string(cloud.height) +
                             " grid (intrinsics fit RMS " + std::to_string(fit.rms_px) +
                             " px, max_fit_rms_px " + std::to_string(max_fit_rms_px_) +
                             "): are WIDTH and HEIGHT right? Give the intrinsics to read it "
                             "anyway");
          }
        }
        images = organized_images(cloud);
      } else {
        if (!have_camera_ || camera_.width <= 0 || camera_.height <= 0) {
          throw StageError(what + " is an unorganized cloud (height 1, " +
                           std::to_string(cloud.size()) +
                           " points): give the intrinsics (param 'intrinsics', or fx, fy, cx, "
                           "cy, width and height) to re-project it into an image");
        }
        camera = camera_;
        images = projected_images(cloud, camera);
      }
    } catch (const StageError& error) {
      if (!playback_.skips_unusable()) throw;
      io::FilePlayback::warn_skipped(ctx, error);
      continue;
    }

    FrameHeader header;
    header.camera = camera;
    header.frame.index = playback_.frame_index();
    header.frame.stem = file.stem().string();
    header.frame.stream_frames = playback_.stream_frames();
    header.frame.timestamp_ns = playback_.nominal_timestamp_ns();
    if (images.out_of_range > 0) {
      ctx.warn(what + ": " + std::to_string(images.out_of_range) +
               " points beyond 65.535 m left out (depth is 16-bit mm)");
    }
    const double pixels = static_cast<double>(images.depth.total());
    ctx.metric("valid_ratio", static_cast<double>(cv::countNonZero(images.depth)) / pixels);
    if (!images.labels.empty()) {
      const std::int32_t count = apply_label_scheme(images.labels, scheme_);
      kLabels(ctx, LabelImage::make(header, std::move(images.labels), count));
    }
    kDepth(ctx, DepthImage::make(header, std::move(images.depth)));
    playback_.emitted();
    return;
  }
}

}  // namespace facet::pcd
