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

std::string png_data_uri(const fs::path& file, int max_width) {
  cv::Mat image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  if (image.empty()) return "";
  const bool labels = image.channels() == 1 && image.depth() != CV_8U;
  if (labels) image = coloured_labels(image);
  if (max_width > 0 && image.cols > max_width) {
    const double scale = static_cast<double>(max_width) / image.cols;
    cv::Mat small;
    cv::resize(image, small, cv::Size(), scale, scale, labels ? cv::INTER_NEAREST : cv::INTER_AREA);
    image = small;
  }
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".png", image, bytes)) return "";
  return "data:image/png;base64," + base64(bytes);
}

std::vector<ImageRow> collect_variant_images(
    const std::vector<std::pair<std::string, fs::path>>& variant_dirs, int frames, int max_width) {
  // folder -> stems seen in any variant; sorted, so every variant shows the same frames.
  std::map<std::string, std::set<std::string>> stems;
  for (const auto& [name, dir] : variant_dirs) {
    std::error_code error;
    for (auto it = fs::recursive_directory_iterator(dir, error);
         !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
      if (!it->is_regular_file() || it->path().extension() != ".png") continue;
      const fs::path relative = fs::relative(it->path().parent_path(), dir);
      stems[relative.generic_string()].insert(it->path().stem().string());
    }
  }
  std::vector<ImageRow> rows;
  for (const auto& [folder, folder_stems] : stems) {
    int shown = 0;
    for (const auto& stem : folder_stems) {
      if (shown++ >= frames) break;
      ImageRow row{folder, stem, {}};
      for (const auto& [name, dir] : variant_dirs) {
        const fs::path file = dir / folder / (stem + ".png");
        std::error_code error;
        row.data_uris.push_back(fs::is_regular_file(file, error) ? png_data_uri(file, max_width)
                                                                 : "");
      }
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace facet::cli
