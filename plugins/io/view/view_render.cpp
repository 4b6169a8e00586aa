#include "view/view_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>

#include "io/label_palette.hpp"
#include "io/overlay_sink.hpp"

namespace facet::view {
namespace {

constexpr double kCaptionScale = 0.5;

std::uint8_t unit_to_byte(float value) {
  const float clamped = std::clamp(value, 0.0F, 1.0F);
  return static_cast<std::uint8_t>(std::lround(clamped * 255.0F));
}

void draw_caption(cv::Mat& image, const std::string& caption) {
  if (caption.empty()) return;
  int baseline = 0;
  const cv::Size size =
      cv::getTextSize(caption, cv::FONT_HERSHEY_SIMPLEX, kCaptionScale, 1, &baseline);
  cv::rectangle(image, cv::Rect(0, 0, size.width + 8, size.height + baseline + 8),
                cv::Scalar(0, 0, 0), cv::FILLED);
  cv::putText(image, caption, cv::Point(4, size.height + 4), cv::FONT_HERSHEY_SIMPLEX,
              kCaptionScale, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
}

}  // namespace

cv::Mat render_depth(const cv::Mat& depth) {
  io::OverlayStyle style;
  const io::GreyRange range = io::auto_grey_range(depth);
  style.near_m = range.near_m;
  style.far_m = range.far_m;
  return io::render_overlay(depth, cv::Mat(), cv::Mat(), style);
}

cv::Mat render_normals(const cv::Mat& normals) {
  CV_Assert(normals.type() == CV_32FC3);
  cv::Mat image(normals.size(), CV_8UC3, cv::Scalar(0, 0, 0));
  for (int y = 0; y < normals.rows; ++y) {
    const auto* src = normals.ptr<cv::Vec3f>(y);
    auto* dst = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < normals.cols; ++x) {
      const cv::Vec3f& n = src[x];
      if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) continue;
      // BGR order: blue carries -z (towards the camera), red carries x.
      dst[x] = cv::Vec3b(unit_to_byte(0.5F * (1.0F - n[2])), unit_to_byte(0.5F * (1.0F + n[1])),
                         unit_to_byte(0.5F * (1.0F + n[0])));
    }
  }
  return image;
}

cv::Mat render_edges(const cv::Mat& score, const cv::Mat& mask) {
  CV_Assert(score.empty() || score.type() == CV_32FC1);
  CV_Assert(mask.empty() || mask.type() == CV_8UC1);
  CV_Assert(score.empty() || mask.empty() || score.size() == mask.size());
  const cv::Size size = score.empty() ? mask.size() : score.size();
  cv::Mat image(size, CV_8UC3, cv::Scalar(0, 0, 0));
  for (int y = 0; y < size.height; ++y) {
    auto* dst = image.ptr<cv::Vec3b>(y);
    const float* s = score.empty() ? nullptr : score.ptr<float>(y);
    const std::uint8_t* m = mask.empty() ? nullptr : mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < size.width; ++x) {
      // No score (no normals there: no measurement) stays black even where the mask has an
      // edge, so the edges between surfaces stand out from the holes.
      if (s != nullptr && !std::isfinite(s[x])) continue;
      if (m != nullptr && m[x] != 0) {
        dst[x] = cv::Vec3b(255, 0, 255);
      } else if (s != nullptr) {
        const std::uint8_t grey = unit_to_byte(s[x]);
        dst[x] = cv::Vec3b(grey, grey, grey);
      }
    }
  }
  return image;
}

cv::Mat render_labels(const cv::Mat& labels, const cv::Mat& depth) {
  CV_Assert(labels.type() == CV_32SC1);
  if (!depth.empty() && depth.size() == labels.size()) {
    io::OverlayStyle style;
    const io::GreyRange range = io::auto_grey_range(depth);
    style.near_m = range.near_m;
    style.far_m = range.far_m;
    style.draw_edges = false;
    return io::render_overlay(depth, labels, cv::Mat(), style);
  }
  cv::Mat image(labels.size(), CV_8UC3, cv::Scalar(0, 0, 0));
  for (int y = 0; y < labels.rows; ++y) {
    const auto* src = labels.ptr<std::int32_t>(y);
    auto* dst = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (src[x] <= 0) continue;
      const io::Rgb colour = io::label_colour(static_cast<std::uint32_t>(src[x]));
      dst[x] = cv::Vec3b(colour.b, colour.g, colour.r);
    }
  }
  return image;
}

cv::Mat tile_images(const std::vector<Tile>& tiles) {
  if (tiles.empty()) return {};
  const cv::Size cell = tiles.front().image.size();
  const int columns = tiles.size() == 1 ? 1 : 2;
  const int rows = static_cast<int>((tiles.size() + 1) / 2);
  cv::Mat canvas(cell.height * rows, cell.width * columns, CV_8UC3, cv::Scalar(0, 0, 0));
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int column = static_cast<int>(i % 2);
    const int row = static_cast<int>(i / 2);
    cv::Mat target =
        canvas(cv::Rect(column * cell.width, row * cell.height, cell.width, cell.height));
    if (tiles[i].image.size() == cell) {
      tiles[i].image.copyTo(target);
    } else {
      cv::resize(tiles[i].image, target, cell, 0.0, 0.0, cv::INTER_NEAREST);
    }
    draw_caption(target, tiles[i].caption);
  }
  return canvas;
}

cv::Mat render_view(const ViewInputs& inputs, Show show, double scale) {
  const cv::Mat no_depth;
  const cv::Mat& depth = inputs.depth != nullptr ? inputs.depth->depth : no_depth;
  cv::Mat image;
  switch (show) {
    case Show::depth:
      if (inputs.depth != nullptr) image = render_depth(depth);
      break;
    case Show::normals:
      if (inputs.normals != nullptr) image = render_normals(inputs.normals->normals);
      break;
    case Show::edges:
      if (inputs.edges != nullptr) image = render_edges(inputs.edges->score, inputs.edges->mask);
      break;
    case Show::labels:
      if (inputs.labels != nullptr) image = render_labels(inputs.labels->labels, depth);
      break;
    case Show::all: {
      std::vector<Tile> tiles;
      if (inputs.depth != nullptr) tiles.push_back({"depth", render_depth(depth)});
      if (inputs.normals != nullptr)
        tiles.push_back({"normals", render_normals(inputs.normals->normals)});
      if (inputs.edges != nullptr)
        tiles.push_back({"edges", render_edges(inputs.edges->score, inputs.edges->mask)});
      if (inputs.labels != nullptr)
        tiles.push_back({"labels", render_labels(inputs.labels->labels, depth)});
      image = tile_images(tiles);
      break;
    }
  }
  if (image.empty() || scale == 1.0) return image;
  cv::Mat scaled;
  cv::resize(image, scaled, cv::Size(), scale, scale,
             scale > 1.0 ? cv::INTER_NEAREST : cv::INTER_AREA);
  return scaled;
}

}  // namespace facet::view
