#include "planes/support_planes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "facet/image_checks.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "planes/world_up.hpp"

namespace facet::planes {
namespace {

struct Candidate {
  std::int32_t patch = 0;
  std::int64_t size_px = 0;
  std::vector<float> points;  // x, y, z of each valid pixel of the patch
  PlaneModel model;
};

// Large patches, largest first (ties: lower id first), with their points.
std::vector<Candidate> collect_candidates(const cv::Mat& labels, const cv::Mat& xyz,
                                          std::int32_t count, std::int64_t min_px,
                                          int max_candidates) {
  std::vector<std::int64_t> size_px(static_cast<std::size_t>(count) + 1, 0);
  const auto* label = labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = labels.total();
  for (std::size_t i = 0; i < total; ++i) {
    const std::int32_t id = label[i];
    if (id > 0 && id <= count && std::isfinite(point[3 * i + 2])) ++size_px[id];
  }
  std::vector<std::int32_t> ids;
  for (std::int32_t id = 1; id <= count; ++id) {
    if (size_px[id] >= min_px) ids.push_back(id);
  }
  std::stable_sort(ids.begin(), ids.end(),
                   [&](std::int32_t a, std::int32_t b) { return size_px[a] > size_px[b]; });
  if (ids.size() > static_cast<std::size_t>(max_candidates)) ids.resize(max_candidates);

  std::vector<Candidate> candidates(ids.size());
  std::vector<int> slot(static_cast<std::size_t>(count) + 1, -1);
  for (std::size_t c = 0; c < ids.size(); ++c) {
    candidates[c].patch = ids[c];
    candidates[c].size_px = size_px[ids[c]];
    candidates[c].points.reserve(3 * static_cast<std::size_t>(size_px[ids[c]]));
    slot[ids[c]] = static_cast<int>(c);
  }
  for (std::size_t i = 0; i < total; ++i) {
    const std::int32_t id = label[i];
    if (id <= 0 || id > count || slot[id] < 0 || !std::isfinite(point[3 * i + 2])) continue;
    auto& out = candidates[slot[id]].points;
    out.insert(out.end(), point + 3 * i, point + 3 * i + 3);
  }
  return candidates;
}

}  // namespace

StageSpec SupportPlaneStage::spec() {
  return StageSpec(
             "planes.support",
             "Support and background planes (table, floor, walls) from large surface patches.\n"
             "Paper sec. II-B d. Every patch of at least candidate_min_px valid points is a "
             "candidate (largest first, at most max_candidates): a plane is fitted to it by "
             "ransac_iterations random point triples of the patch, scored at distance_m / 2, "
             "then refitted by least squares. A candidate becomes a support plane when it is "
             "the dominant horizontal plane (the largest candidate facing world up), or when "
             "it covers at least min_view_fraction of the valid pixels and at most "
             "max_behind_fraction of the object candidates (points on no support plane) lie "
             "more than behind_margin_m behind it; this is re-evaluated until nothing changes, "
             "so a table is accepted once the floor and walls behind it are. Box faces fail: "
             "the rest of their box lies behind them. Then, largest first, every valid point "
             "not yet taken within distance_m of a support plane joins it, also out of its "
             "patch. Patches left with fewer than min_segment_px points are dropped.")
      .input<LabelImage>("patches", "Surface patches, CV_32SC1 ids 1..count (grow.surfaces).")
      .input<PointImage>("points", "3D points, CV_32FC3 in metres, NaN = invalid; same size.")
      .output<SupportPlanes>("planes",
                             "Support planes (ids 1..N, largest candidate first; normal towards "
                             "the camera, inliers, rms, horizontal) and world up.")
      .output<LabelImage>("plane_labels", "CV_32SC1 plane id per pixel, 0 = on no plane.")
      .output<LabelImage>("patches",
                          "The input patches with plane points and dropped segments set to 0; "
                          "ids and count unchanged (ids may now be unused).")
      .param("distance_m", 0.012,
             "delta: a point closer than this to a support plane belongs to it. RANSAC scores "
             "its hypotheses at delta / 2.",
             {.unit = "m", .min = 0.001, .max = 0.5, .origin = "paper (12 mm)"})
      .param("ransac_iterations", 20,
             "Random 3-point hypotheses per candidate. Samples come from one surface patch, "
             "which is nearly all plane, so a few suffice.",
             {.min = 1.0, .max = 10000.0, .origin = "authors' code (20)"})
      .param("candidate_min_px", 2500,
             "N_bg: patches with at least this many valid points are plane candidates. Low "
             "enough for wall and floor fragments at the edge of the view; box faces among "
             "the candidates are rejected by the support test, not by size. A pixel count: "
             "scale it with the image area (x1/4 at 320x240).",
             {.unit = "px",
              .min = 3.0,
              .max = 1.0e8,
              .origin = "paper's N_bg = 2500, here at 640x480 (the authors' 320x240 value x4, "
                        "10000, leaves wall fragments of the uncropped OSD frame as objects)"})
      .param("max_candidates", 16, "The largest this many candidates are fitted and judged.",
             {.min = 1.0,
              .max = 32.0,
              .origin = "measured: the 45 mOSD frames have at most 8 patches over 10000 px"})
      .param("min_view_fraction", 0.01,
             "A plane that is not the dominant horizontal one must hold at least this share of "
             "the valid pixels (sampled, within distance_m) to be background.",
             {.min = 0.0,
              .max = 1.0,
              .origin = "measured: the wall fragment of the uncropped OSD frame holds 0.02"})
      .param("max_behind_fraction", 0.05,
             "A plane that is not the dominant horizontal one is background only if at most "
             "this share of the object candidates lies behind it.",
             {.min = 0.0, .max = 1.0, .origin = "measured on mOSD and the uncropped OSD frame"})
      .param("behind_margin_m", 0.05,
             "A point counts as behind a plane when it is further than this on the plane's far "
             "side: sensor noise, mixed pixels and the front edge of a table top (a few cm "
             "thick) stay within it, while a box's far side lies beyond.",
             {.unit = "m",
              .min = 0.0,
              .max = 1.0,
              .origin = "measured: 0.03 and 0.05 score alike on mOSD and the uncropped OSD "
                        "frame; 0.05 keeps a 4 cm table top in front of a dominant floor"})
      .param("min_object_fraction", 0.02,
             "Floor of the behind-test denominator, as a share of the valid pixels, so that a "
             "few stray points do not veto a plane when almost nothing else is left.",
             {.min = 0.0, .max = 1.0, .origin = "measured"})
      .param("max_support_behind_fraction", 0.1,
             "An object face stands on the table: a candidate with more than this share of the "
             "dominant plane's points behind it is not background (unless it holds "
             "large_view_fraction of the view).",
             {.min = 0.0, .max = 1.0, .origin = "measured on mOSD and the uncropped OSD frame"})
      .param("large_view_fraction", 0.15,
             "Candidates holding this share of the valid pixels skip the "
             "max_support_behind_fraction test (a table seen above a dominant floor).",
             {.min = 0.0, .max = 1.0, .origin = "measured: mOSD box faces hold at most 0.13"})
      .param("sample_stride_px", 2,
             "The support test looks at every n-th row and column (the assignment to planes "
             "is always per pixel).",
             {.unit = "px",
              .min = 1.0,
              .max = 16.0,
              .origin = "measured: same decisions, 1/4 of "
                        "the time"})
      .param("horizontal_max_deg", 10.0,
             "alpha_z: a plane is horizontal when its normal is within this angle of world up.",
             {.unit = "deg", .min = 0.0, .max = 90.0, .origin = "paper (10 deg)"})
      .param("up", "auto",
             "World up in the camera frame: 'auto' takes the normal of the largest candidate "
             "within up_prior_max_deg of the camera's up (-y); or a vector 'x,y,z' (camera "
             "frame: x right, y down, z forward), e.g. '0,-1,0' for a level camera.",
             {.origin = "ALGORITHM.md: from a parameter or the dominant horizontal plane"})
      .param("up_prior_max_deg", 60.0,
             "auto up: the dominant horizontal plane is the largest candidate whose normal is "
             "within this angle of the camera's -y axis (a camera looking down at a table at "
             "up to this pitch). With a given up, horizontal_max_deg is used instead.",
             {.unit = "deg", .min = 0.0, .max = 90.0, .origin = "measured: mOSD tables 25-50 deg"})
      .param("min_segment_px", 20,
             "N_seg: patches left with fewer points than this are dropped (set to 0).",
             {.unit = "px", .min = 0.0, .max = 1.0e6, .origin = "paper: N_seg = 5 at 320x240, x4"})
      .param("seed", 1, "Seed of the RANSAC random numbers, reset every frame.",
             {.min = 0.0, .max = 4294967295.0, .origin = "any; fixed for reproducible results"})
      .concurrency(Concurrency::clonable);
}

SupportPlaneStage::SupportPlaneStage(const Params& params)
    : candidate_min_px_(params.get_int("candidate_min_px")),
      max_candidates_(static_cast<int>(params.get_int("max_candidates"))),
      horizontal_max_deg_(params.get_double("horizontal_max_deg")),
      up_prior_max_deg_(params.get_double("up_prior_max_deg")),
      min_segment_px_(params.get_int("min_segment_px")),
      seed_(static_cast<std::uint32_t>(params.get_int("seed"))) {
  const auto distance_m = static_cast<float>(params.get_double("distance_m"));
  fit_rule_.ransac_iterations = static_cast<int>(params.get_int("ransac_iterations"));
  fit_rule_.inlier_distance_m = distance_m / 2.0F;
  support_rule_.inlier_distance_m = distance_m;
  support_rule_.behind_margin_m = static_cast<float>(params.get_double("behind_margin_m"));
  support_rule_.min_view_fraction = params.get_double("min_view_fraction");
  support_rule_.max_behind_fraction = params.get_double("max_behind_fraction");
  support_rule_.min_object_fraction = params.get_double("min_object_fraction");
  support_rule_.max_support_behind_fraction = params.get_double("max_support_behind_fraction");
  support_rule_.large_view_fraction = params.get_double("large_view_fraction");
  support_rule_.sample_stride_px = static_cast<int>(params.get_int("sample_stride_px"));
  try {
    up_ = parse_up(params.get_string("up"));
  } catch (const std::invalid_argument& error) {
    throw StageError(error.what());
  }
}

void SupportPlaneStage::process(ProcessContext& ctx) {
  const auto& patches = ctx.input<LabelImage>("patches");
  const auto& points = ctx.input<PointImage>("points");
  require_type(patches.labels, CV_32SC1, "patches");
  require_type(points.points, CV_32FC3, "points");
  require_same_size(patches.labels, "patches", points.points, "points");
  const cv::Mat labels = patches.labels.isContinuous() ? patches.labels : patches.labels.clone();
  const cv::Mat xyz = points.points.isContinuous() ? points.points : points.points.clone();

  // Candidates and their planes; the generator restarts every frame, so a frame's result does
  // not depend on the frames before it (and clones agree).
  std::mt19937 rng(seed_);
  std::vector<Candidate> candidates =
      collect_candidates(labels, xyz, patches.count, candidate_min_px_, max_candidates_);
  std::vector<PlaneModel> models;
  std::vector<std::int64_t> sizes;
  for (auto& candidate : candidates) {
    if (auto model = fit_plane(candidate.points, fit_rule_, rng)) {
      models.push_back(*model);
      sizes.push_back(candidate.size_px);
    }
  }

  const Eigen::Vector3f camera_up(0.0F, -1.0F, 0.0F);
  const int dominant = up_ ? dominant_horizontal(models, *up_, horizontal_max_deg_)
                           : dominant_horizontal(models, camera_up, up_prior_max_deg_);
  Eigen::Vector3f up = up_.value_or(camera_up);
  if (!up_ && dominant >= 0) up = models[dominant].normal;
  const std::vector<CandidateEvidence> evidence =
      decide_support(xyz, models, dominant, support_rule_);

  // Assignment, largest plane first: every valid point not yet taken within delta.
  SupportPlanes planes;
  static_cast<FrameHeader&>(planes) = points;
  planes.up = up.cast<double>();
  LabelImage plane_labels;
  static_cast<FrameHeader&>(plane_labels) = points;
  plane_labels.labels = cv::Mat::zeros(labels.size(), CV_32SC1);
  auto* plane_of = plane_labels.labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = labels.total();
  const double min_cos_horizontal = std::cos(horizontal_max_deg_ * std::numbers::pi / 180.0);
  for (std::size_t c = 0; c < models.size(); ++c) {
    if (!evidence[c].accepted) continue;
    const PlaneModel& model = models[c];
    const auto id = static_cast<std::int32_t>(planes.planes.size() + 1);
    std::int64_t inliers = 0;
    double squared_sum = 0.0;
    for (std::size_t i = 0; i < total; ++i) {
      if (plane_of[i] != 0 || !std::isfinite(point[3 * i + 2])) continue;
      const float d = model.signed_distance_m(point + 3 * i);
      if (std::abs(d) > support_rule_.inlier_distance_m) continue;
      plane_of[i] = id;
      ++inliers;
      squared_sum += static_cast<double>(d) * d;
    }
    Plane plane;
    plane.id = id;
    plane.normal = model.normal.cast<double>();
    plane.offset_m = model.offset_m;
    plane.inliers = inliers;
    plane.rms_m = inliers > 0 ? std::sqrt(squared_sum / static_cast<double>(inliers)) : 0.0;
    plane.horizontal = plane.normal.dot(planes.up) >= min_cos_horizontal;
    planes.planes.push_back(plane);
  }

  // What is left for objects: patches minus plane points, minus segments too small to matter.
  LabelImage remaining;
  static_cast<FrameHeader&>(remaining) = patches;
  remaining.count = patches.count;
  remaining.labels = labels.clone();
  auto* left = remaining.labels.ptr<std::int32_t>();
  std::vector<std::int64_t> left_px(static_cast<std::size_t>(std::max(0, patches.count)) + 1, 0);
  std::int64_t valid_px = 0;
  std::int64_t plane_px = 0;
  for (std::size_t i = 0; i < total; ++i) {
    if (std::isfinite(point[3 * i + 2])) ++valid_px;
    if (plane_of[i] != 0) {
      left[i] = 0;
      ++plane_px;
    } else if (left[i] > 0 && left[i] <= patches.count) {
      ++left_px[left[i]];
    } else {
      left[i] = 0;  // ids outside 1..count are not patches
    }
  }
  for (std::size_t i = 0; i < total; ++i) {
    if (left[i] != 0 && left_px[left[i]] < min_segment_px_) left[i] = 0;
  }

  if (valid_px == 0) {
    ctx.warn("no valid points: no planes");
  } else if (planes.planes.empty()) {
    ctx.warn("no support plane found: every patch is left for objects");
  }
  ctx.metric("planes", static_cast<double>(planes.planes.size()));
  ctx.metric("plane_ratio",
             valid_px > 0 ? static_cast<double>(plane_px) / static_cast<double>(valid_px) : 0.0);
  plane_labels.count = static_cast<std::int32_t>(planes.planes.size());
  ctx.output("planes", std::move(planes));
  ctx.output("plane_labels", std::move(plane_labels));
  ctx.output("patches", std::move(remaining));
}

}  // namespace facet::planes
