#include "edges/normal_edge_stage.hpp"

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <utility>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace facet::edges {

namespace {

const In<NormalImage> kNormals{"normals", "Unit surface normals, CV_32FC3; NaN = no normal."};
const Out<EdgeImage> kEdges{
    "edges",
    "score: CV_32FC1 in [0, 1], the combined mean |cosine| between neighbouring normals "
    "(1 = flat; 0 at pixels without a normal and at the image border within `pixels`, and "
    "where `invalid_neighbours` says so; never NaN). mask: CV_8UC1, 255 = edge (score <= "
    "threshold), 0 = surface."};
const Param<int> kPixels{"pixels",
                         3,
                         "R: how many adjacent pixels are averaged along each of the 8 directions "
                         "(diagonals step k pixels in x and in y). 3 gives the broad, closed edges "
                         "region growing needs; 1 gives thin edges that may leave gaps.",
                         {.unit = "px",
                          .choices = {std::int64_t{1}, std::int64_t{3}},
                          .origin = "paper (\"three adjacent pixels\", sec. II-A b and Fig. 2)"}};
const Param<double> kThreshold{
    "threshold",
    0.85,
    "A pixel is surface where its score is above this, edge otherwise (0.85 = an angle "
    "of 31.8 degrees). The right value depends on the space the normals were computed "
    "in: the paper tuned it on raw Kinect disparity at 320x240; with metric normals a "
    "prototype on the mOSD frames peaked near 0.89. Choose it together with the "
    "normal stage.",
    {.min = 0.0,
     .max = 1.0,
     .origin = "paper (theta_max = 0.85, tuned in raw-disparity space); not re-measured "
               "for metric normals here"}};
const EnumParam<InvalidNeighbours> kInvalidNeighbours{
    "invalid_neighbours",
    InvalidNeighbours::edge,
    {{InvalidNeighbours::skip, "skip"}, {InvalidNeighbours::edge, "edge"}},
    "What a direction counts for when one of its `pixels` neighbours has no normal (a "
    "hole in the depth, or within the normal stage's radius of one). skip: the "
    "direction is left out, and the pixel is scored by its valid directions (0 when it "
    "has none); a hole stays an edge itself but marks nothing around it. edge: the pixel "
    "scores 0, so every hole grows into an edge band `pixels` wider on each side; a "
    "dropout line along an object's outline then covers a small or far object whole.",
    {.origin = "edge: mOSD whole objects F 0.975 (skip 0.974: pieces of an object "
               "beyond a hole become objects of their own); skip: generated development "
               "sets 0.872 -> 0.882 tuning, 0.881 -> 0.885 checking, most beyond 1.4 m "
               "(docs/evaluation.md, 'Holes beside surfaces')"}};

}  // namespace

StageSpec normal_edge_spec(std::string name, std::string doc) {
  StageSpec spec(std::move(name), std::move(doc));
  return spec.declare(kNormals, kEdges, kPixels, kThreshold, kInvalidNeighbours)
      .concurrency(Concurrency::clonable);
}

NormalEdgeStage::NormalEdgeStage(const Params& params, DirectionCombine combine)
    : scorer_(kPixels(params), combine, kInvalidNeighbours(params)),
      threshold_(static_cast<float>(kThreshold(params))) {}

void NormalEdgeStage::process(ProcessContext& ctx) {
  const NormalImage& input = kNormals(ctx);
  cv::Mat score = scorer_.score(input.normals, ctx.parallel_runner());
  cv::Mat mask = edge_mask(score, threshold_);
  const double edge_pixels = cv::countNonZero(mask);
  ctx.metric("edge_ratio", edge_pixels / static_cast<double>(mask.total()));
  kEdges(ctx, EdgeImage::make(input, std::move(score), std::move(mask)));
}

}  // namespace facet::edges
