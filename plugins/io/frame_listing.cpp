#include "io/frame_listing.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <opencv2/core.hpp>
#include <sstream>
#include <system_error>

#include "facet/error.hpp"
#include "io/natural_order.hpp"
#include "io/other_sources.hpp"

namespace fs = std::filesystem;

namespace facet::io {
namespace {

bool has_png_extension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".png";
}

template <class Keep>
std::vector<fs::path> regular_files(const fs::path& folder, Keep keep) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (entry.is_regular_file(error) && keep(entry.path())) files.push_back(entry.path());
  }
  if (error) {
    throw StageError("cannot list folder '" + folder.string() + "': " + error.message());
  }
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return natural_less(a.filename().string(), b.filename().string());
  });
  return files;
}

constexpr std::string_view kFlatDepthSuffix = "-depth.png";
constexpr std::string_view kFlatLabelSuffix = "-label.png";

bool is_flat_depth(const fs::path& file) {
  const std::string name = file.filename().string();
  return name.size() > kFlatDepthSuffix.size() &&
         name.compare(name.size() - kFlatDepthSuffix.size(), kFlatDepthSuffix.size(),
                      kFlatDepthSuffix) == 0;
}

// Stems for the depth files; in the flat layout also the label file next to each.
void name_frames(FrameListing& listing) {
  listing.stems.clear();
  listing.label_files.clear();
  for (const fs::path& file : listing.depth_files) {
    if (listing.layout == FrameLayout::flat) {
      const std::string name = file.filename().string();
      const std::string stem = name.substr(0, name.size() - kFlatDepthSuffix.size());
      listing.stems.push_back(stem);
      listing.label_files.push_back(file.parent_path() / (stem + std::string(kFlatLabelSuffix)));
    } else {
      listing.stems.push_back(file.stem().string());
    }
  }
}

FrameListing list_tum(const fs::path& list_file) {
  std::ifstream in(list_file);
  if (!in) throw StageError("cannot open TUM list '" + list_file.string() + "'");
  FrameListing listing;
  listing.layout = FrameLayout::tum;
  listing.root = list_file.has_parent_path() ? list_file.parent_path() : fs::path(".");
  listing.depth_units_per_metre = 5000.0;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string where = list_file.string() + ":" + std::to_string(line_number);
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    std::vector<std::string> words;
    for (std::string word; fields >> word;)
      words.push_back(word);
    if (words.empty()) continue;
    if (words.size() != 2 && words.size() != 4) {
      throw StageError(where +
                       ": expected 'timestamp path' or 'timestamp path timestamp path', "
                       "got " +
                       std::to_string(words.size()) + " fields");
    }
    // The pair whose path names depth (associate.py writes rgb and depth in either order);
    // a plain list has one pair.
    std::size_t pair = 0;
    if (words.size() == 4) {
      const bool first = words[1].find("depth") != std::string::npos;
      const bool second = words[3].find("depth") != std::string::npos;
      if (first == second) {
        throw StageError(where + ": cannot tell which of '" + words[1] + "' and '" + words[3] +
                         "' is the depth image (expected exactly one path containing 'depth')");
      }
      pair = first ? 0 : 2;
    }
    std::int64_t timestamp_ns = 0;
    if (!parse_seconds(words[pair], timestamp_ns)) {
      throw StageError(where + ": '" + words[pair] + "' is not a timestamp in seconds");
    }
    const fs::path depth = fs::path(words[pair + 1]).is_absolute() ? fs::path(words[pair + 1])
                                                                   : listing.root / words[pair + 1];
    listing.depth_files.push_back(depth);
    listing.timestamps_ns.push_back(timestamp_ns);
  }
  if (listing.depth_files.empty()) {
    throw StageError("no frames: TUM list '" + list_file.string() + "' lists no depth images");
  }
  name_frames(listing);
  return listing;
}

FrameListing list_glob(const std::string& pattern_path) {
  const fs::path pattern(pattern_path);
  const fs::path folder = pattern.has_parent_path() ? pattern.parent_path() : fs::path(".");
  if (is_glob(folder.string())) {
    throw StageError("path '" + pattern_path +
                     "': wildcards are supported in the file name only, not in folders");
  }
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw StageError("path '" + pattern_path + "': folder '" + folder.string() +
                     "' does not exist");
  }
  const std::string name_pattern = pattern.filename().string();
  FrameListing listing;
  listing.root = fs::absolute(folder, error).lexically_normal().parent_path();
  listing.depth_files = regular_files(folder, [&](const fs::path& file) {
    return wildcard_match(name_pattern, file.filename().string());
  });
  if (listing.depth_files.empty()) {
    throw StageError("path '" + pattern_path + "' matches no files");
  }
  if (const OtherSource other = other_source_of_files(listing.depth_files);
      other != OtherSource::none) {
    throw StageError("path " + other_source_advice(other, pattern_path, PathHolds::several));
  }
  // DIR/*-depth.png: the flat layout, whose dataset folder is DIR itself.
  if (std::all_of(listing.depth_files.begin(), listing.depth_files.end(), is_flat_depth)) {
    listing.layout = FrameLayout::flat;
    listing.root = folder;
  }
  name_frames(listing);
  return listing;
}

FrameListing list_folder(const std::string& folder_path) {
  const fs::path folder(folder_path);
  std::error_code error;
  if (!fs::exists(folder, error)) {
    throw StageError("dataset folder '" + folder_path + "' does not exist");
  }
  if (fs::is_regular_file(folder, error) && folder.extension() == ".txt") return list_tum(folder);
  if (const OtherSource other = other_source_of_file(folder);
      other != OtherSource::none && !fs::is_directory(folder, error)) {
    throw StageError("path " + other_source_advice(other, folder_path, PathHolds::one_file));
  }
  if (!fs::is_directory(folder, error)) {
    throw StageError("path '" + folder_path +
                     "' is not a folder (give a dataset folder, a TUM list such as "
                     "'depth.txt', or a glob such as 'frames/*.png')");
  }
  // A TUM sequence also has depth/, but its frames are the list's (with their timestamps).
  for (const char* list : {"associations.txt", "depth.txt"}) {
    if (fs::is_regular_file(folder / list, error)) return list_tum(folder / list);
  }
  const fs::path depth_folder = folder / "depth";
  FrameListing listing;
  listing.root = folder;
  if (!fs::is_directory(depth_folder, error)) {
    listing.layout = FrameLayout::flat;
    listing.depth_files = regular_files(folder, is_flat_depth);
    if (listing.depth_files.empty()) {
      if (const OtherSource other = other_source_in_folder(folder); other != OtherSource::none) {
        throw StageError("dataset folder " +
                         other_source_advice(other, folder_path, PathHolds::several));
      }
      throw StageError("dataset folder '" + folder_path + "' has no depth/ folder (expected '" +
                       depth_folder.string() +
                       "/*.png'), no *-depth.png files and no TUM list (associations.txt or "
                       "depth.txt)");
    }
    name_frames(listing);
    return listing;
  }
  listing.depth_files = regular_files(depth_folder, has_png_extension);
  if (listing.depth_files.empty()) {
    throw StageError("no frames: '" + depth_folder.string() + "' holds no .png files");
  }
  name_frames(listing);
  return listing;
}

}  // namespace

bool is_glob(const std::string& path) {
  return path.find_first_of("*?") != std::string::npos;
}

FrameListing list_frames(const std::string& path) {
  if (path.empty()) throw StageError("param 'path' is empty: set a dataset folder or a glob");
  return is_glob(path) ? list_glob(path) : list_folder(path);
}

bool parse_seconds(const std::string& text, std::int64_t& nanoseconds) {
  const std::size_t dot = text.find('.');
  const std::string whole = text.substr(0, dot);
  std::string fraction = dot == std::string::npos ? std::string() : text.substr(dot + 1);
  const auto digits = [](const std::string& s) {
    return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
  };
  if (whole.empty() || whole.size() > 10 || !digits(whole) || !digits(fraction)) return false;
  fraction = (fraction + "000000000").substr(0, 9);
  // Ten digits of seconds can exceed what nanoseconds in 64 bits hold (about 9.2e9 s, the year
  // 2262): such a time is no capture time.
  constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;
  const std::int64_t seconds = std::stoll(whole);
  const std::int64_t part = std::stoll(fraction);
  if (seconds > (std::numeric_limits<std::int64_t>::max() - part) / kNanosecondsPerSecond) {
    return false;
  }
  nanoseconds = seconds * kNanosecondsPerSecond + part;
  return true;
}

cv::Mat depth_to_millimetres(const cv::Mat& depth, double units_per_metre) {
  if (units_per_metre == 1000.0) return depth;
  cv::Mat mm(depth.size(), CV_16UC1);
  const double to_mm = 1000.0 / units_per_metre;
  for (int row = 0; row < depth.rows; ++row) {
    const auto* in = depth.ptr<std::uint16_t>(row);
    auto* out = mm.ptr<std::uint16_t>(row);
    for (int col = 0; col < depth.cols; ++col) {
      const double value = std::round(in[col] * to_mm);
      out[col] = value <= 65535.0 ? static_cast<std::uint16_t>(value) : 0;
    }
  }
  return mm;
}

// Iterative matcher with one backtrack point (the last '*'), linear in practice.
bool wildcard_match(std::string_view pattern, std::string_view name) {
  std::size_t p = 0;
  std::size_t n = 0;
  std::size_t star = std::string_view::npos;
  std::size_t star_n = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      star_n = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++star_n;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*')
    ++p;
  return p == pattern.size();
}

}  // namespace facet::io
