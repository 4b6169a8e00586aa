#pragma once
// What io.view draws, as BGR images (CV_8UC3): pure functions of the inputs, so they are tested
// without a window. Depth and labels are drawn as io.overlay draws them (same greys, same
// segment colours), so a live view and the written overlays look alike.

#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "facet/types/images.hpp"

namespace facet::view {

// Depth (CV_16UC1 mm or CV_32FC1 m) as grey: near bright, far dark, no measurement black; the
// range is the 1st to 99th percentile of the frame's valid depths.
cv::Mat render_depth(const cv::Mat& depth);

// Unit normals (CV_32FC3, pointing towards the camera, so z < 0) as colours: red = (1 + x) / 2,
// green = (1 + y) / 2, blue = (1 - z) / 2, so a surface facing the camera is blue, one facing
// left (x < 0) loses red, one facing up (y < 0) loses green; NaN (no normal) black.
cv::Mat render_normals(const cv::Mat& normals);

// The edge score (CV_32FC1, 0..1, higher = smoother) as grey and the edge decision (CV_8UC1,
// 255 = edge) in magenta; black where the score is NaN (no surface there). Either may be empty.
cv::Mat render_edges(const cv::Mat& score, const cv::Mat& mask);

// Segments (CV_32SC1, 0 = background) in io.overlay's colours, blended over the depth's grey
// when `depth` is given (not empty, same size), else on black; borders drawn.
cv::Mat render_labels(const cv::Mat& labels, const cv::Mat& depth);

// One picture with a caption in its top left corner.
struct Tile {
  std::string caption;
  cv::Mat image;  // CV_8UC3
};

// The tiles side by side, two per row, each scaled to the first tile's size; black where a row
// is short. Empty when there are no tiles.
cv::Mat tile_images(const std::vector<Tile>& tiles);

// What one frame brings to io.view: each may be missing.
struct ViewInputs {
  const DepthImage* depth = nullptr;
  const NormalImage* normals = nullptr;
  const EdgeImage* edges = nullptr;
  const LabelImage* labels = nullptr;
};

// What io.view shows: one of its inputs, or all of them tiled.
enum class Show { depth, normals, edges, labels, all };

// The picture for `show`, scaled by `scale`. `labels` is drawn over depth when depth is there;
// `all` tiles every input present. Empty when the input `show` needs is missing.
cv::Mat render_view(const ViewInputs& inputs, Show show, double scale);

}  // namespace facet::view
