#include "io/overlay_sink.hpp"

#include <string>

#include "facet/contract.hpp"
#include "facet/image_checks.hpp"
#include "facet/types/images.hpp"
#include "io/output_folder.hpp"
#include "io/png_files.hpp"

namespace facet::io {
namespace {

const In<DepthImage> kDepth{"depth", "Depth, CV_16UC1 in mm or CV_32FC1 in m; names the file."};
const In<LabelImage> kLabels{
    "labels", "Segment ids of the same size, CV_32SC1, 0 = not a segment; what io.labels takes."};
const OptionalIn<EdgeImage> kEdges{
    "edges",
    "Normal edges of the same size; the mask (CV_8UC1, 255 = edge) is "
    "drawn in edge_colour when draw_edges is set."};
const Param<std::string> kDir{
    "dir", "out/overlay", "Output folder, created if missing.", {.required = true}};
const Param<double> kNearM{
    "near_m",
    0.0,
    "Depth drawn brightest with a fixed range (far_m > 0); nearer is as bright.",
    {.unit = "m", .min = 0.0, .max = 100.0}};
const Param<double> kFarM{
    "far_m",
    0.0,
    "Depth drawn darkest with a fixed range; farther is as dark. 0 = range of each "
    "frame: its 1st to 99th percentile of valid depth, so a few stray pixels do not "
    "wash out the picture.",
    {.unit = "m",
     .min = 0.0,
     .max = 100.0,
     .origin = "auto: works for any scene; fix it to compare frames by brightness"}};
const Param<double> kAlpha{
    "alpha",
    0.5,
    "Weight of the segment colour over the grey: 0 = grey only, 1 = solid.",
    {.min = 0.0, .max = 1.0, .origin = "half: colour and the depth's shading both show"}};
const Param<bool> kDrawBorders{"draw_borders", true,
                               "Draw the border pixels of every segment in border_colour."};
const Param<Rgb> kBorderColour{"border_colour", Rgb{0, 0, 0},
                               "Colour of segment borders, #rrggbb."};
const Param<bool> kDrawEdges{"draw_edges", true,
                             "Draw the edge mask of the 'edges' input (when connected) in "
                             "edge_colour."};
const Param<Rgb> kEdgeColour{"edge_colour",
                             Rgb{0xff, 0x00, 0xff},
                             "Colour of edge pixels, #rrggbb.",
                             {.origin = "magenta: rare in the palette's blended colours"}};

}  // namespace

StageSpec OverlaySink::spec() {
  StageSpec spec("io.overlay",
                 "Writes a colour picture of each frame as <dir>/<stem>.png (8-bit RGB).\n"
                 "Depth is the grey background: near is bright, far is dark grey (48), no "
                 "measurement is black. Segments (label != 0) are blended over it in a colour "
                 "that depends on the id only, so an object keeps its colour from frame to frame "
                 "and in io.cloud's point clouds; label 0 keeps the grey. Segment borders (pixels "
                 "with a 4-neighbour of another id) and the edge mask of the optional 'edges' "
                 "input (where there is depth) are drawn on top in solid colours. Frames with an "
                 "empty label packet are not written, as with io.labels. Format and palette: "
                 "docs/data-formats.md.");
  return spec
      .declare(kDepth, kLabels, kEdges, kDir, kNearM, kFarM, kAlpha, kDrawBorders, kBorderColour,
               kDrawEdges, kEdgeColour)
      .concurrency(Concurrency::serial);
}

OverlaySink::OverlaySink(const Params& params) : dir_(kDir(params)) {
  style_.near_m = kNearM(params);
  style_.far_m = kFarM(params);
  style_.alpha = kAlpha(params);
  style_.draw_borders = kDrawBorders(params);
  style_.border_colour = kBorderColour(params);
  style_.draw_edges = kDrawEdges(params);
  style_.edge_colour = kEdgeColour(params);
  if (style_.far_m > 0.0 && style_.far_m <= style_.near_m) {
    throw StageError("far_m (" + std::to_string(style_.far_m) + ") must be above near_m (" +
                     std::to_string(style_.near_m) + "), or 0 for a range per frame");
  }
}

void OverlaySink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_);
  earlier_ = EarlierResults::survey(dir_, ".png");
}

void OverlaySink::process(ProcessContext& ctx) {
  earlier_.warn_once(ctx);
  const DepthImage& depth = kDepth(ctx);
  const std::filesystem::path file = frame_file(dir_, depth.frame);
  if (kLabels.packet(ctx).empty()) return;
  // The packets keep their types' formats (facet/types/images.hpp): depth CV_16UC1 or CV_32FC1,
  // ids CV_32SC1 and never negative, a CV_8UC1 edge mask; only the sizes are checked here.
  const cv::Mat& ids = kLabels(ctx).labels;
  require_same_size(depth.depth, "depth", ids, "labels");
  cv::Mat mask;
  const EdgeImage* edges_input = style_.draw_edges ? kEdges(ctx) : nullptr;
  if (edges_input != nullptr) {
    require_same_size(depth.depth, "depth", edges_input->mask, "edges");
    mask = edges_input->mask;
  }
  write_png(file, render_overlay(depth.depth, ids, mask, style_, ctx.parallel_runner()));
}

}  // namespace facet::io
