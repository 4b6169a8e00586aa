#include "planes/support_planes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "facet/algo/patch_contacts.hpp"
#include "facet/image_checks.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"
#include "planes/scene_model.hpp"
#include "planes/table_outline.hpp"
#include "planes/world_up.hpp"

namespace facet::planes {
namespace {

struct Candidate {
  std::int32_t patch = 0;
  std::int64_t size_px = 0;
  std::vector<float> points;  // x, y, z of each valid pixel of the patch
  PlaneModel model;

  Eigen::Vector3f centroid_m() const {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i + 2 < points.size(); i += 3)
      sum += Eigen::Vector3d(points[i], points[i + 1], points[i + 2]);
    const auto count = static_cast<double>(points.size() / 3);
    if (count == 0) return Eigen::Vector3f::Zero();
    return (sum / count).cast<float>();
  }
};

// Large patches, largest first (ties: lower id first), with at most max_points of their points
// each, evenly spread: every k-th point in raster order. A few thousand points fix a plane as
// well as the hundreds of thousands of a table top, at a fraction of the copying.
std::vector<Candidate> collect_candidates(const cv::Mat& labels, const cv::Mat& xyz,
                                          std::int32_t count, std::int64_t min_px,
                                          int max_candidates, std::int64_t max_points) {
  const auto* label = labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = labels.total();
  // Sizes count patch pixels (those of grow.surfaces all have a valid point); only the sampled
  // points are checked below.
  std::vector<std::int64_t> size_px(static_cast<std::size_t>(count) + 1, 0);
  for (std::size_t i = 0; i < total; ++i) {
    const std::int32_t id = label[i];
    if (id > 0 && id <= count) ++size_px[id];
  }
  std::vector<std::int32_t> ids;
  for (std::int32_t id = 1; id <= count; ++id) {
    if (size_px[id] >= min_px) ids.push_back(id);
  }
  std::stable_sort(ids.begin(), ids.end(),
                   [&](std::int32_t a, std::int32_t b) { return size_px[a] > size_px[b]; });
  if (ids.size() > static_cast<std::size_t>(max_candidates)) ids.resize(max_candidates);
  if (ids.empty()) return {};

  std::vector<Candidate> candidates(ids.size());
  // Per patch id: its candidate slot (-1 = none), the sampling step and the points to skip
  // before the next sample.
  std::vector<int> slot(static_cast<std::size_t>(count) + 1, -1);
  std::vector<std::int64_t> step(static_cast<std::size_t>(count) + 1, 1);
  std::vector<std::int64_t> skip(static_cast<std::size_t>(count) + 1, 0);
  for (std::size_t c = 0; c < ids.size(); ++c) {
    const std::int32_t id = ids[c];
    candidates[c].patch = id;
    candidates[c].size_px = size_px[id];
    step[id] = std::max<std::int64_t>(1, (size_px[id] + max_points - 1) / max_points);
    candidates[c].points.reserve(3 * static_cast<std::size_t>(size_px[id] / step[id] + 1));
    slot[id] = static_cast<int>(c);
  }
  for (std::size_t i = 0; i < total; ++i) {
    const std::int32_t id = label[i];
    if (id <= 0 || id > count || slot[id] < 0) continue;
    if (skip[id] > 0) {
      --skip[id];
      continue;
    }
    const float* p = point + 3 * i;
    if (!std::isfinite(p[2])) continue;  // the next point of the patch is taken instead
    skip[id] = step[id] - 1;
    auto& out = candidates[slot[id]].points;
    out.push_back(p[0]);
    out.push_back(p[1]);
    out.push_back(p[2]);
  }
  return candidates;
}

// The table's outline is the hull of the points on every 8th row and column: a few thousand of
// them, whose hull is within a few millimetres of the full one.
constexpr int kOutlineStridePx = 8;
// A patch outlines the table when at least this share of its points lies on the table's level.
constexpr double kOutlinePatchShare = 0.25;

// The valid pixels of the frame, counted on every 4th row (the level sizes they are compared
// with are coarse shares of the view).
std::int64_t estimate_valid_px(const cv::Mat& xyz) {
  constexpr int kRowStep = 4;
  std::int64_t valid = 0;
  for (int row = 0; row < xyz.rows; row += kRowStep) {
    const auto* p = xyz.ptr<float>(row);
    for (int col = 0; col < xyz.cols; ++col)
      valid += std::isfinite(p[3 * col + 2]) ? 1 : 0;
  }
  return valid * kRowStep;
}

// The points of `candidate` farther than `distance_m` from `model`, and the centroid of the others
// (those on the plane).
struct PlaneSplit {
  std::vector<float> off;
  Eigen::Vector3f on_centroid_m = Eigen::Vector3f::Zero();
};

PlaneSplit split_by_plane(const Candidate& candidate, const PlaneModel& model, float distance_m) {
  PlaneSplit split;
  Eigen::Vector3d on_sum = Eigen::Vector3d::Zero();
  std::size_t on_count = 0;
  for (std::size_t i = 0; i + 2 < candidate.points.size(); i += 3) {
    const float* p = &candidate.points[i];
    if (std::abs(model.signed_distance_m(p)) > distance_m) {
      split.off.insert(split.off.end(), p, p + 3);
    } else {
      on_sum += Eigen::Vector3d(p[0], p[1], p[2]);
      ++on_count;
    }
  }
  if (on_count > 0) split.on_centroid_m = (on_sum / static_cast<double>(on_count)).cast<float>();
  return split;
}

// Two fits of one patch that are the same plane (within `angle_cos` and `distance_m` at the
// second fit's centroid): the second saw the first one's noisy fringe, not a plane of its own.
bool same_plane(const PlaneModel& a, const PlaneModel& b, const Eigen::Vector3f& b_centroid,
                float angle_cos, float distance_m) {
  return std::abs(a.normal.dot(b.normal)) >= angle_cos &&
         std::abs(a.signed_distance_m(b_centroid.data())) <= distance_m;
}

}  // namespace

StageSpec SupportPlaneStage::spec() {
  return StageSpec(
             "planes.support",
             "Support and background planes (table, floor, walls) from large surface patches.\n"
             "Paper sec. II-B d. Every patch of at least candidate_min_px valid points is a "
             "candidate (largest first, at most max_candidates): a plane is fitted to it by "
             "ransac_iterations random point triples of the patch, scored at distance_m / 2, "
             "then refitted by least squares. The scene model (docs/planes.md) first picks the "
             "table: horizontal candidates are grouped into levels (centroids within "
             "min_object_height_m of one plane); the largest level is the table, unless a level "
             "far above it (max_object_height_m) holds large_view_fraction of the view (a table "
             "above the floor) or a level a little below it holds min_table_fraction (the "
             "largest level is then a board or box lying on that table). Levels raised above "
             "the table by up to max_object_height_m are object tops (books, trays, boxes lying "
             "flat) and never support planes. Any other candidate becomes a background plane "
             "when it covers at least min_view_fraction of the valid pixels and at most "
             "max_behind_fraction of the object candidates (points on no support plane) lie "
             "more than behind_margin_m behind it; this is re-evaluated until nothing changes, "
             "so a table is accepted once the floor and walls behind it are. Box faces fail: "
             "the rest of their box lies behind them. Then, largest first, every valid point "
             "not yet taken within distance_m of a support plane joins it, also out of its "
             "patch, except the points of object faces. What a plane leaves of a patch is split "
             "into its connected pieces (8-neighbours closer than split_max_distance_m), each a "
             "patch of its own: a table patch that ran onto the tops of objects leaves one "
             "piece per top, not one patch spanning them. Patches left with fewer than "
             "min_segment_px points are dropped. The table's visible extent (a convex outline) "
             "goes with the planes, for grow.blobs.")
      .input<LabelImage>("patches", "Surface patches, CV_32SC1 ids 1..count (grow.surfaces).")
      .input<PointImage>("points", "3D points, CV_32FC3 in metres, NaN = invalid; same size.")
      .output<SupportPlanes>("planes",
                             "Support planes (ids 1..N, largest candidate first; normal towards "
                             "the camera, inliers, rms, horizontal, role: table, floor or wall), "
                             "world up, the table's id and its outline.")
      .output<LabelImage>("plane_labels", "CV_32SC1 plane id per pixel, 0 = on no plane.")
      .output<LabelImage>("patches",
                          "The input patches with plane points and dropped segments set to 0; "
                          "ids kept (ids may now be unused); the pieces a plane cut off a "
                          "patch numbered from the input's count + 1 on.")
      .output<PatchAdjacency>("adjacency",
                              "Pairs (a < b, sorted) of the output patches that touch "
                              "(8-neighbours), as grow.surfaces' adjacency, for the patches "
                              "left.")
      .param("distance_m", 0.010,
             "delta: a point closer than this to a support plane belongs to it. RANSAC scores "
             "its hypotheses at delta / 2.",
             {.unit = "m",
              .min = 0.001,
              .max = 0.5,
              .origin = "paper: 12 mm; swept 8-14 mm: 10 mm lies on the plateau of mOSD and of "
                        "both generated sets, 12 mm not on that of the tuning set "
                        "(docs/evaluation.md)"})
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
      .param("fit_max_points", 10000,
             "A candidate's plane is fitted (RANSAC and least-squares refit) to at most this "
             "many of its points, every k-th in raster order.",
             {.min = 3.0,
              .max = 1.0e8,
              .origin = "measured: same planes and scores on mOSD as with all points, a "
                        "fraction of the time"})
      .param("object_face_off_plane_fraction", 0.5,
             "A patch with at least this share of its points more than 2 distance_m from every "
             "support plane is an object face: its points within distance_m of a plane stay "
             "with it (the bottom band of an object standing on the table). So is a patch whose "
             "points near a horizontal plane lie on average more than min_object_height_m above "
             "it (a book 1 cm thick). Other points within distance_m join the plane. Above 1, "
             "only the height test keeps points from the planes.",
             {.min = 0.0,
              .max = 2.0,
              .origin = "measured on mOSD: recall of objects' lower borders (docs/planes.md)"})
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
             "Horizontal candidates (within horizontal_max_deg of up) holding this share of the "
             "valid pixels skip the max_support_behind_fraction test (a table seen above a "
             "dominant floor); a large vertical face standing on the table stays an object.",
             {.min = 0.0, .max = 1.0, .origin = "measured: mOSD box faces hold at most 0.13"})
      .param("sample_stride_px", 4,
             "The support test looks at every n-th row and column (the assignment to planes "
             "is always per pixel).",
             {.unit = "px",
              .min = 1.0,
              .max = 16.0,
              .origin = "measured: the same decisions at 1, 2 and 4 on mOSD and the uncropped "
                        "OSD frame; 4 reads 1/16 of the points"})
      .param("min_object_height_m", 0.006,
             "Scene model: horizontal candidates whose centroids lie within this height of one "
             "another's plane are one level (the fragments of one table top); a level or a patch "
             "raised above the table by more is the top of an object lying on it. The smallest "
             "thickness of a flat object that is found (with Kinect noise at 1 m: about 1 cm).",
             {.unit = "m",
              .min = 0.0,
              .max = 0.1,
              .origin = "measured: plateau of generated scenes with books 1-4 cm thick "
                        "(docs/evaluation.md)"})
      .param("max_object_height_m", 0.3,
             "Scene model: a horizontal level raised above the table by up to this much is an "
             "object top; farther above, and holding large_view_fraction of the view, it is a "
             "table above the floor. A level this much or less below the largest one, holding "
             "min_table_fraction, is the table that level stands on.",
             {.unit = "m",
              .min = 0.0,
              .max = 10.0,
              .origin = "tables stand 0.4 m and more above the floor; objects for a gripper are "
                        "lower"})
      .param("min_table_fraction", 0.05,
             "Scene model: the least share of the valid pixels that a level below the largest "
             "one needs to be taken for the table (the largest level is then a board lying on "
             "it).",
             {.min = 0.0, .max = 1.0, .origin = "measured on generated crowded tables"})
      .param("horizontal_max_deg", 10.0,
             "alpha_z: a plane is horizontal when its normal is within this angle of world up.",
             {.unit = "deg", .min = 0.0, .max = 90.0, .origin = "paper (10 deg)"})
      .param("up", "auto",
             "World up in the camera frame: 'auto' takes the normal of the largest candidate "
             "within up_prior_max_deg of the camera's up (-y); or a vector 'x,y,z' (camera "
             "frame: x right, y down, z forward), e.g. '0,-1,0' for a level camera.",
             {.origin = "ALGORITHM.md: from a parameter or the dominant horizontal plane"})
      .param("up_prior_max_deg", 80.0,
             "auto up: the dominant horizontal plane is the largest candidate whose normal is "
             "within this angle of the camera's -y axis (a camera looking down at a table at "
             "up to this pitch). A wall facing a camera pitched down lies more than 90 deg from "
             "it. With a given up, horizontal_max_deg is used instead.",
             {.unit = "deg",
              .min = 0.0,
              .max = 90.0,
              .origin = "mOSD tables 25-50 deg; generated views pitched down 30-70 deg (60 lost "
                        "the table of every view pitched more steeply, docs/evaluation.md)"})
      .param("min_segment_px", 20,
             "N_seg: patches left with fewer points than this are dropped (set to 0).",
             {.unit = "px", .min = 0.0, .max = 1.0e6, .origin = "paper: N_seg = 5 at 320x240, x4"})
      .param("split_max_distance_m", 0.01,
             "Gate of the split of what a plane leaves of a patch: two of its pixels are one "
             "piece when they are 8-neighbours closer than this in 3D (growing with the square "
             "of the depth beyond split_growth_start_m).",
             {.unit = "m",
              .min = 0.0,
              .max = 1.0,
              .origin = "grow.blobs' Delta_blob (the same neighbour linkage)"})
      .param(
          "split_growth_start_m", 1.2,
          "Beyond this depth split_max_distance_m grows with the square of the depth; 0 "
          "keeps it fixed.",
          {.unit = "m", .min = 0.0, .max = 100.0, .origin = "grow.blobs' distance_growth_start_m"})
      .param("planes_per_patch", 2,
             "Planes fitted to one candidate patch: what a fit leaves more than 2 distance_m "
             "off its plane, when that is at least candidate_min_px, is fitted again (a fit "
             "within horizontal_max_deg and 2 distance_m of the one before is the same plane "
             "and ends the search). Where no normal edge parts them, one patch spans a far table "
             "and the wall behind it; one plane per patch then finds only the wall, and the "
             "frame loses its table. 1 = the paper's one plane per patch.",
             {.min = 1.0,
              .max = 4.0,
              .origin = "2: generated checking set with PCA normals 0.835 -> 0.890 (seed 1008's "
                        "view lost its table); the default graph's figures unchanged within "
                        "0.001 (docs/planes.md)"})
      .param("seed", 1, "Seed of the RANSAC random numbers, reset every frame.",
             {.min = 0.0, .max = 4294967295.0, .origin = "any; fixed for reproducible results"})
      .concurrency(Concurrency::clonable);
}

SupportPlaneStage::SupportPlaneStage(const Params& params)
    : candidate_min_px_(params.get_int("candidate_min_px")),
      max_candidates_(static_cast<int>(params.get_int("max_candidates"))),
      planes_per_patch_(static_cast<int>(params.get_int("planes_per_patch"))),
      max_fit_points_(params.get_int("fit_max_points")),
      object_face_off_plane_fraction_(params.get_double("object_face_off_plane_fraction")),
      min_object_height_m_(static_cast<float>(params.get_double("min_object_height_m"))),
      horizontal_max_deg_(params.get_double("horizontal_max_deg")),
      up_prior_max_deg_(params.get_double("up_prior_max_deg")),
      min_segment_px_(params.get_int("min_segment_px")),
      split_gate_(static_cast<float>(params.get_double("split_max_distance_m")),
                  static_cast<float>(params.get_double("split_growth_start_m"))),
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
  support_rule_.min_cos_horizontal = std::cos(horizontal_max_deg_ * std::numbers::pi / 180.0);
  support_rule_.sample_stride_px = static_cast<int>(params.get_int("sample_stride_px"));
  table_rule_.min_cos_horizontal = support_rule_.min_cos_horizontal;
  table_rule_.level_tolerance_m = static_cast<float>(params.get_double("min_object_height_m"));
  table_rule_.max_object_height_m = static_cast<float>(params.get_double("max_object_height_m"));
  table_rule_.min_table_fraction = params.get_double("min_table_fraction");
  table_rule_.large_view_fraction = support_rule_.large_view_fraction;
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
  std::vector<Candidate> candidates = collect_candidates(
      labels, xyz, patches.count, candidate_min_px_, max_candidates_, max_fit_points_);
  // A patch may hold more than one plane: where no normal edge parts them (a far table running
  // into the wall behind it, seen at a grazing angle), one patch spans both. What a fit leaves
  // clearly off its plane (beyond 2 delta), when it is a candidate's worth of pixels, is fitted
  // again, up to planes_per_patch planes.
  struct Fitted {
    PlaneModel model;
    std::int64_t size_px;
    Eigen::Vector3f centroid;
  };
  std::vector<Fitted> fitted;
  const float off_plane_m = 2.0F * support_rule_.inlier_distance_m;
  const float same_plane_cos = static_cast<float>(support_rule_.min_cos_horizontal);
  for (auto& candidate : candidates) {
    Candidate part = std::move(candidate);
    std::optional<PlaneModel> previous;
    for (int plane = 0; plane < planes_per_patch_; ++plane) {
      const auto model = fit_plane(part.points, fit_rule_, rng);
      if (!model) break;
      const Eigen::Vector3f centroid = part.centroid_m();
      if (previous && same_plane(*previous, *model, centroid, same_plane_cos, off_plane_m)) break;
      // The last plane allowed, or a patch whose off-plane points are too few for another
      // candidate, keeps the whole of what is left, size and centroid, as one plane per patch did.
      const bool last = plane + 1 == planes_per_patch_;
      PlaneSplit split = last ? PlaneSplit{} : split_by_plane(part, *model, off_plane_m);
      const auto sampled = static_cast<std::int64_t>(part.points.size() / 3);
      const std::int64_t off_px =
          sampled > 0 ? part.size_px * static_cast<std::int64_t>(split.off.size() / 3) / sampled
                      : 0;
      if (last || off_px < candidate_min_px_) {
        fitted.push_back({*model, part.size_px, centroid});
        break;
      }
      // A patch that holds another plane: this plane takes its own points' size and centroid (the
      // levels of the scene model compare centroids with planes), not the whole patch's.
      fitted.push_back({*model, part.size_px - off_px, split.on_centroid_m});
      previous = model;
      part.points = std::move(split.off);
      part.size_px = off_px;
    }
  }
  // Largest first, as the candidates were: the table and the assignment order rely on it.
  std::stable_sort(fitted.begin(), fitted.end(),
                   [](const Fitted& a, const Fitted& b) { return a.size_px > b.size_px; });
  std::vector<PlaneModel> models;
  std::vector<std::int64_t> sizes;
  std::vector<Eigen::Vector3f> centroids;
  for (const Fitted& f : fitted) {
    models.push_back(f.model);
    sizes.push_back(f.size_px);
    centroids.push_back(f.centroid);
  }

  const Eigen::Vector3f camera_up(0.0F, -1.0F, 0.0F);
  const int dominant = up_ ? dominant_horizontal(models, *up_, horizontal_max_deg_)
                           : dominant_horizontal(models, camera_up, up_prior_max_deg_);
  Eigen::Vector3f up = up_.value_or(camera_up);
  if (!up_ && dominant >= 0) up = models[dominant].normal;
  const TableChoice table =
      dominant >= 0
          ? choose_table(models, centroids, sizes, estimate_valid_px(xyz), up, table_rule_)
          : TableChoice{-1, std::vector<CandidateRole>(models.size()), {}};
  const std::vector<CandidateEvidence> evidence =
      decide_support(xyz, models, table.table, table.roles, up, support_rule_);

  // Assignment, largest plane first: a valid point within delta of a support plane joins the
  // first such plane in candidate order (what taking the planes one after the other would
  // give), unless it belongs to an object face, a patch that lies mostly well off the planes:
  // the bottom band of a box side, within delta of the table it stands on, stays with the box.
  std::vector<PlaneModel> accepted;
  std::vector<PlaneRole> roles;
  std::int32_t table_id = 0;
  for (std::size_t c = 0; c < models.size(); ++c) {
    if (!evidence[c].accepted) continue;
    accepted.push_back(models[c]);
    const bool horizontal = models[c].normal.dot(up) >= support_rule_.min_cos_horizontal;
    if (table.table >= 0 && table.roles[c] == CandidateRole::table) {
      roles.push_back(PlaneRole::table);
      if (static_cast<int>(c) == table.table) table_id = static_cast<std::int32_t>(accepted.size());
    } else if (horizontal && table.table >= 0 && table.height_m[c] < 0.0F) {
      roles.push_back(PlaneRole::floor);
    } else {
      roles.push_back(PlaneRole::wall);
    }
  }
  const float delta_m = support_rule_.inlier_distance_m;

  SupportPlanes planes;
  static_cast<FrameHeader&>(planes) = points;
  planes.up = up.cast<double>();
  LabelImage plane_labels;
  static_cast<FrameHeader&>(plane_labels) = points;
  plane_labels.labels.create(labels.size(), CV_32SC1);
  // What is left for objects: patches minus plane points, minus segments too small to matter.
  LabelImage remaining;
  static_cast<FrameHeader&>(remaining) = patches;
  remaining.count = patches.count;
  remaining.labels.create(labels.size(), CV_32SC1);

  auto* plane_of = plane_labels.labels.ptr<std::int32_t>();
  auto* left = remaining.labels.ptr<std::int32_t>();
  const auto* label = labels.ptr<std::int32_t>();
  const auto* point = xyz.ptr<float>();
  const std::size_t total = labels.total();
  const auto patch_slots = static_cast<std::size_t>(std::max(0, patches.count)) + 1;
  // Slot 0 collects pixels of no patch (or of an id outside 1..count).
  const auto patch_slot = [&](std::int32_t id) {
    return id > 0 && id <= patches.count ? static_cast<std::size_t>(id) : std::size_t{0};
  };
  // Per patch: valid points, those clearly off the planes (beyond 2 delta from all), their
  // summed height above the table, and per (patch, plane) the points within delta and their
  // squared distances, so that the patches are judged and the plane statistics made with no
  // second look at the points.
  const std::size_t plane_count = accepted.size();
  const std::size_t table_c = table_id > 0 ? static_cast<std::size_t>(table_id - 1) : plane_count;
  std::vector<std::int64_t> patch_px(patch_slots, 0);
  std::vector<std::int64_t> off_px(patch_slots, 0);
  // Of the points that are within delta of the table (and of no larger plane before it).
  std::vector<double> table_height_sum_m(patch_slots, 0.0);
  std::vector<std::int64_t> near_px(patch_slots * plane_count, 0);
  std::vector<double> near_squared_m2(patch_slots * plane_count, 0.0);
  std::int64_t valid_px = 0;
  for (std::size_t i = 0; i < total; ++i) {
    const float* p = point + 3 * i;
    std::int32_t near = 0;
    const std::size_t slot = patch_slot(label[i]);
    if (std::isfinite(p[2])) {
      ++valid_px;
      bool off = true;
      for (std::size_t c = 0; c < plane_count; ++c) {
        const float d = accepted[c].signed_distance_m(p);
        const float distance = std::abs(d);
        off = off && distance > 2.0F * delta_m;
        if (distance <= delta_m) {
          near = static_cast<std::int32_t>(c + 1);
          ++near_px[slot * plane_count + c];
          near_squared_m2[slot * plane_count + c] += static_cast<double>(d) * d;
          if (c == table_c) table_height_sum_m[slot] += d;
          break;
        }
      }
      ++patch_px[slot];
      off_px[slot] += off ? 1 : 0;
    }
    plane_of[i] = near;
  }
  // Which patches give their points within delta to the planes: all but object faces. A face
  // that lies mostly well off the planes keeps them from every plane (the bottom band of a box
  // side). A patch whose points within delta of the table lie on average more than half of
  // min_object_height_m above it keeps them from the table's level and the floor: the top of a
  // book 1 cm thick (its points lie min_object_height_m and more above), the bottom band of a
  // flat object's side (evenly spread over 0..delta). The table's own points lie around 0.
  std::vector<char> joins_any(patch_slots, 1);
  std::vector<char> joins_horizontal(patch_slots, 1);
  for (std::size_t slot = 1; slot < patch_slots; ++slot) {
    const auto size = static_cast<double>(patch_px[slot]);
    joins_any[slot] = static_cast<double>(off_px[slot]) < object_face_off_plane_fraction_ * size;
    const std::int64_t table_near_px =
        table_c < plane_count ? near_px[slot * plane_count + table_c] : 0;
    const bool raised = table_near_px > 0 &&
                        table_height_sum_m[slot] > 0.5 * static_cast<double>(min_object_height_m_) *
                                                       static_cast<double>(table_near_px);
    joins_horizontal[slot] = joins_any[slot] != 0 && !raised ? 1 : 0;
  }
  std::vector<char> horizontal_support(plane_count, 0);
  for (std::size_t c = 0; c < plane_count; ++c) {
    horizontal_support[c] = roles[c] != PlaneRole::wall ? 1 : 0;
  }
  const auto joins = [&](std::size_t slot, std::size_t c) {
    return horizontal_support[c] != 0 ? joins_horizontal[slot] != 0 : joins_any[slot] != 0;
  };
  std::vector<std::int64_t> inliers(plane_count, 0);
  std::vector<double> squared_sum(plane_count, 0.0);
  for (std::size_t slot = 0; slot < patch_slots; ++slot) {
    for (std::size_t c = 0; c < plane_count; ++c) {
      if (!joins(slot, c)) continue;
      inliers[c] += near_px[slot * plane_count + c];
      squared_sum[c] += near_squared_m2[slot * plane_count + c];
    }
  }

  std::vector<std::int64_t> left_px(patch_slots, 0);
  std::int64_t plane_px = 0;
  for (std::size_t i = 0; i < total; ++i) {
    const std::size_t slot = patch_slot(label[i]);
    if (plane_of[i] != 0 && joins(slot, static_cast<std::size_t>(plane_of[i] - 1))) {
      left[i] = 0;
      ++plane_px;
      continue;
    }
    plane_of[i] = 0;
    left[i] = static_cast<std::int32_t>(slot);
    ++left_px[slot];
  }
  // A patch that gave points to a plane and kept some may have kept several pieces (the table's
  // patch run onto object tops through gaps in the edges): one patch each.
  std::vector<char> cut(patch_slots, 0);
  bool any_cut = false;
  for (std::size_t slot = 1; slot < patch_slots; ++slot) {
    cut[slot] = left_px[slot] > 0 && left_px[slot] < patch_px[slot] ? 1 : 0;
    any_cut = any_cut || cut[slot] != 0;
  }
  if (any_cut) {
    remaining.count = pieces_.split(remaining.labels, patches.count, cut, xyz, split_gate_);
    left_px.assign(static_cast<std::size_t>(remaining.count) + 1, 0);
    for (std::size_t i = 0; i < total; ++i)
      ++left_px[static_cast<std::size_t>(left[i])];
  }
  // Segments too small to matter; slot 0 (no patch) is never kept.
  const std::size_t left_slots = left_px.size();
  std::vector<char> too_small(left_slots, 0);
  bool small_segments = false;
  for (std::size_t slot = 1; slot < left_slots; ++slot) {
    const std::int64_t size = left_px[slot];
    too_small[slot] = size > 0 && size < min_segment_px_;
    small_segments = small_segments || too_small[slot] != 0;
  }
  if (small_segments) {
    for (std::size_t i = 0; i < total; ++i) {
      if (too_small[static_cast<std::size_t>(left[i])] != 0) left[i] = 0;
    }
  }

  for (std::size_t c = 0; c < accepted.size(); ++c) {
    Plane plane;
    plane.id = static_cast<std::int32_t>(c + 1);
    plane.normal = accepted[c].normal.cast<double>();
    plane.offset_m = accepted[c].offset_m;
    plane.inliers = inliers[c];
    plane.rms_m =
        inliers[c] > 0 ? std::sqrt(squared_sum[c] / static_cast<double>(inliers[c])) : 0.0;
    plane.horizontal = plane.normal.dot(planes.up) >= support_rule_.min_cos_horizontal;
    plane.role = roles[c];
    planes.planes.push_back(plane);
  }
  if (table_id > 0) {
    // Every plane of the table's level outlines the table.
    std::vector<char> table_ids(plane_count + 1, 0);
    for (std::size_t c = 0; c < plane_count; ++c)
      table_ids[c + 1] = roles[c] == PlaneRole::table;
    planes.table_id = table_id;
    // The table's patches: those of which a good share lies on the table's plane. A share, not a
    // majority: beyond 2 m a table's own disparity steps put much of it more than delta off.
    std::vector<char> table_patches(patch_slots, 0);
    for (std::size_t slot = 1; slot < patch_slots; ++slot) {
      std::int64_t on_table_px = 0;
      for (std::size_t c = 0; c < plane_count; ++c) {
        if (table_ids[c + 1] != 0) on_table_px += near_px[slot * plane_count + c];
      }
      table_patches[slot] = static_cast<double>(on_table_px) >=
                            kOutlinePatchShare * static_cast<double>(patch_px[slot]);
    }
    planes.table_outline_m = table_outline(plane_labels.labels, labels, table_patches, xyz,
                                           table_ids, accepted[table_id - 1], up, kOutlineStridePx);
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
  PatchAdjacency adjacency = algo::find_patch_contacts(remaining.labels, remaining.count);
  static_cast<FrameHeader&>(adjacency) = patches;
  ctx.output("patches", std::move(remaining));
  ctx.output("adjacency", std::move(adjacency));
}

}  // namespace facet::planes
