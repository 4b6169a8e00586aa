#include "io/intrinsics_file.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include "facet/error.hpp"

namespace facet::io {
namespace {

// yaml-cpp marks are 0-based; editors count from 1.
std::string location(const std::filesystem::path& file, const YAML::Mark& mark) {
  if (mark.is_null()) return file.string();
  return file.string() + ":" + std::to_string(mark.line + 1) + ":" +
         std::to_string(mark.column + 1);
}

template <class T>
T required_number(const std::filesystem::path& file, const YAML::Node& root, const char* key,
                  const char* expected) {
  const YAML::Node node = root[key];
  if (!node) {
    throw StageError(file.string() + ": missing key '" + key + "' (expected " + expected + ")");
  }
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    const std::string text = node.IsScalar() ? "'" + node.Scalar() + "'" : "a non-scalar value";
    throw StageError(location(file, node.Mark()) + ": key '" + key + "' must be " + expected +
                     ", got " + text);
  }
}

// A value of a key outside its plausible range: refused, since a focal length of 1e300 or a
// NaN principal point runs without error and silently gives no objects.
void check_range(const std::filesystem::path& file, const YAML::Node& root, const char* key,
                 double value, double min, double max, const char* meaning) {
  if (std::isfinite(value) && value >= min && value <= max) return;
  std::ostringstream text;
  text << location(file, root[key].Mark()) << ": key '" << key << "' is " << value << ", "
       << meaning << " lies in [" << min << ", " << max << "]";
  throw StageError(text.str());
}

// yaml-cpp keeps one of two equal keys without a word; a file that says fx twice is refused.
void check_unique_keys(const std::filesystem::path& file, const YAML::Node& root) {
  std::set<std::string> seen;
  for (const auto& entry : root) {
    if (!entry.first.IsScalar()) continue;
    if (!seen.insert(entry.first.Scalar()).second) {
      throw StageError(location(file, entry.first.Mark()) + ": key '" + entry.first.Scalar() +
                       "' appears twice");
    }
  }
}

}  // namespace

CameraIntrinsics read_intrinsics(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    throw StageError("intrinsics file '" + file.string() +
                     "' not found (needed for the frame size and for back-projection; set "
                     "param 'intrinsics')");
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::Exception& e) {
    throw StageError(location(file, e.mark) + ": not valid YAML: " + e.msg);
  }
  if (!root.IsMap())
    throw StageError(file.string() + ": expected a map of fx, fy, cx, cy, width, height");
  check_unique_keys(file, root);

  CameraIntrinsics camera;
  camera.fx = required_number<double>(file, root, "fx", "a focal length in pixels");
  camera.fy = required_number<double>(file, root, "fy", "a focal length in pixels");
  camera.cx = required_number<double>(file, root, "cx", "a principal point x in pixels");
  camera.cy = required_number<double>(file, root, "cy", "a principal point y in pixels");
  camera.width = required_number<int>(file, root, "width", "an image width in pixels");
  camera.height = required_number<int>(file, root, "height", "an image height in pixels");
  check_range(file, root, "width", camera.width, 1, kMaxIntrinsicsSizePx, "an image width");
  check_range(file, root, "height", camera.height, 1, kMaxIntrinsicsSizePx, "an image height");
  for (const char* key : {"fx", "fy"}) {
    check_range(file, root, key, key[1] == 'x' ? camera.fx : camera.fy, kMinFocalLengthPx,
                kMaxFocalLengthPx, "a focal length in pixels");
  }
  // The principal point may lie off the image (a crop), but not by more than the image's size.
  check_range(file, root, "cx", camera.cx, -camera.width, 2.0 * camera.width,
              "a principal point x (within the image widened by its width on each side)");
  check_range(file, root, "cy", camera.cy, -camera.height, 2.0 * camera.height,
              "a principal point y (within the image widened by its height on each side)");
  return camera;
}

void write_intrinsics(const std::filesystem::path& file, const CameraIntrinsics& camera) {
  std::ofstream out(file);
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  out << "# Pinhole intrinsics of the recorded frames (pixels), as io.frames reads them.\n"
      << "fx: " << camera.fx << "\nfy: " << camera.fy << "\ncx: " << camera.cx
      << "\ncy: " << camera.cy << "\nwidth: " << camera.width << "\nheight: " << camera.height
      << "\n";
  out.close();
  if (!out) throw StageError("cannot write intrinsics file '" + file.string() + "'");
}

}  // namespace facet::io
