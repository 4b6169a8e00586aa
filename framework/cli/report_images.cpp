#include "report_images.hpp"

#include <algorithm>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <system_error>

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

std::string base64(const std::vector<unsigned char>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    const unsigned value = (static_cast<unsigned>(bytes[i]) << 16) |
                           (left > 1 ? static_cast<unsigned>(bytes[i + 1]) << 8 : 0U) |
                           (left > 2 ? static_cast<unsigned>(bytes[i + 2]) : 0U);
    text += kAlphabet[(value >> 18) & 63U];
    text += kAlphabet[(value >> 12) & 63U];
    text += left > 1 ? kAlphabet[(value >> 6) & 63U] : '=';
    text += left > 2 ? kAlphabet[value & 63U] : '=';
  }
  return text;
}

// A bright colour per segment id, the same for the same id in every variant's image, so that
// side-by-side label images are easy to compare.
cv::Vec3b colour_of(std::int32_t id) {
  if (id == 0) return {0, 0, 0};
  std::uint32_t hash = static_cast<std::uint32_t>(id) * 2654435761U;
  hash ^= hash >> 15;
  return {static_cast<unsigned char>(64 + (hash & 0xbfU)),
          static_cast<unsigned char>(64 + ((hash >> 8) & 0xbfU)),
          static_cast<unsigned char>(64 + ((hash >> 16) & 0xbfU))};
}

cv::Mat coloured_labels(const cv::Mat& labels) {
  cv::Mat ids;
  labels.convertTo(ids, CV_32S);
  cv::Mat colour(ids.size(), CV_8UC3);
  for (int y = 0; y < ids.rows; ++y) {
    const auto* in = ids.ptr<std::int32_t>(y);
    auto* out = colour.ptr<cv::Vec3b>(y);
    for (int x = 0; x < ids.cols; ++x)
      out[x] = colour_of(in[x]);
  }
  return colour;
}

}  // namespace

// Shrinks to max_width (nearest neighbour for ids and depth, whose values must not blend) and
// encodes as a data URI.
std::string data_uri_of(cv::Mat image, int max_width, bool nearest) {
  if (max_width > 0 && image.cols > max_width) {
    const double scale = static_cast<double>(max_width) / image.cols;
    cv::Mat small;
    cv::resize(image, small, cv::Size(), scale, scale,
               nearest ? cv::INTER_NEAREST : cv::INTER_AREA);
    image = small;
  }
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".png", image, bytes)) return "";
  return "data:image/png;base64," + base64(bytes);
}

std::string png_data_uri(const fs::path& file, int max_width) {
  cv::Mat image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  if (image.empty()) return "";
  const bool labels = image.channels() == 1 && image.depth() != CV_8U;
  if (labels) image = coloured_labels(image);
  return data_uri_of(image, max_width, labels);
}

std::string depth_data_uri(const fs::path& file, int max_width) {
  const cv::Mat depth = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  if (depth.empty() || depth.type() != CV_16UC1) return "";
  double near_mm = 0.0;
  double far_mm = 0.0;
  cv::minMaxLoc(depth, &near_mm, &far_mm, nullptr, nullptr, depth > 0);
  cv::Mat grey(depth.size(), CV_8UC1, cv::Scalar(0));
  const double span = std::max(far_mm - near_mm, 1.0);
  for (int y = 0; y < depth.rows; ++y) {
    const auto* in = depth.ptr<std::uint16_t>(y);
    auto* out = grey.ptr<unsigned char>(y);
    for (int x = 0; x < depth.cols; ++x) {
      if (in[x] == 0) continue;
      out[x] = static_cast<unsigned char>(255.0 - 195.0 * (in[x] - near_mm) / span);
    }
  }
  return data_uri_of(grey, max_width, true);
}

std::vector<ImageRow> collect_variant_images(
    const std::vector<std::pair<std::string, fs::path>>& variant_dirs,
    const std::vector<std::string>& stems, int max_width) {
  std::set<std::string> folders;
  for (const auto& [name, dir] : variant_dirs) {
    std::error_code error;
    for (auto it = fs::recursive_directory_iterator(dir, error);
         !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
      if (!it->is_regular_file() || it->path().extension() != ".png") continue;
      folders.insert(fs::relative(it->path().parent_path(), dir).generic_string());
    }
  }
  std::vector<ImageRow> rows;
  for (const auto& folder : folders) {
    for (const auto& stem : stems) {
      ImageRow row{folder, stem, {}, {}, {}};
      bool any = false;
      for (const auto& [name, dir] : variant_dirs) {
        const fs::path file = dir / folder / (stem + ".png");
        std::error_code error;
        const bool exists = fs::is_regular_file(file, error);
        row.data_uris.push_back(exists ? png_data_uri(file, max_width) : "");
        any = any || exists;
      }
      if (any) rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace facet::cli
