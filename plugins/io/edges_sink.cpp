#include "io/edges_sink.hpp"

#include <opencv2/core.hpp>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "io/output_folder.hpp"
#include "io/png_files.hpp"

namespace facet::io {
namespace {

const In<EdgeImage> kEdges{"edges", "Edge score (CV_32FC1) and mask (CV_8UC1, 255 = edge)."};
const Param<std::string> kDir{
    "dir", "out/edges", "Output folder, created if missing.", {.required = true}};
const EnumParam<EdgeOutput> kWhat{"what",
                                  EdgeOutput::mask,
                                  {{EdgeOutput::mask, "mask"}, {EdgeOutput::score, "score"}},
                                  "Which image to write.",
                                  {.origin = "mask: the binary decision later stages use"}};

}  // namespace

StageSpec EdgesSink::spec() {
  StageSpec spec("io.edges",
                 "Writes edge images as <dir>/<stem>.png, 8-bit.\n"
                 "With what = mask: 255 = edge, 0 = surface. With what = score: the edge score "
                 "clamped to [0, 1] and scaled to 0..255, so smooth surfaces are bright and "
                 "creases dark.");
  return spec.declare(kEdges, kDir, kWhat).concurrency(Concurrency::serial);
}

EdgesSink::EdgesSink(const Params& params)
    : dir_(kDir(params)), write_score_(kWhat(params) == EdgeOutput::score) {}

void EdgesSink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_);
  earlier_ = EarlierResults::survey(dir_, ".png");
}

void EdgesSink::process(ProcessContext& ctx) {
  earlier_.warn_once(ctx);
  const EdgeImage& edges = kEdges(ctx);
  const std::filesystem::path file = frame_file(dir_, edges.frame);
  if (!write_score_) {
    write_png(file, edges.mask);
    return;
  }
  cv::Mat scaled;
  // NaN scores (which a correct edge stage never emits) would be undefined in convertTo: map to 0.
  cv::Mat clean = edges.score.clone();
  cv::patchNaNs(clean, 0.0);
  clean.convertTo(scaled, CV_8UC1, 255.0);  // saturating: < 0 → 0, > 1 → 255
  write_png(file, scaled);
}

}  // namespace facet::io
