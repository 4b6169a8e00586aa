#include "io/cloud_sink.hpp"

#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <opencv2/core.hpp>

#include "facet/contract.hpp"
#include "facet/image_checks.hpp"
#include "facet/types/images.hpp"
#include "io/label_palette.hpp"
#include "io/output_folder.hpp"

namespace facet::io {
namespace {

// Colour of points without a segment (label 0): a light grey, visible on dark and light
// viewer backgrounds; the palette has no greys.
constexpr Rgb kUnlabelled{170, 170, 170};
constexpr std::size_t kBinaryVertexBytes = 3 * 4 + 3 + 4;  // float x, y, z; uchar r, g, b; uint

const In<PointImage> kPoints{"points", "3D points, CV_32FC3 in metres, NaN = invalid."};
const OptionalIn<LabelImage> kLabels{"labels",
                                     "Segment ids of the same size, CV_32SC1, >= 0; unconnected or "
                                     "empty: every label is 0."};
const Param<std::string> kDir{
    "dir", "out/cloud", "Output folder, created if missing.", {.required = true}};
const EnumParam<PlyFormat> kFormat{
    "format",
    PlyFormat::binary_little_endian,
    {{PlyFormat::binary_little_endian, "binary"}, {PlyFormat::ascii, "ascii"}},
    "PLY encoding: binary (little-endian) or ascii (text).",
    {.origin = "binary: less than half the size of ascii, about 30 times faster to format"}};
const Param<bool> kLabelledOnly{"labelled_only", false,
                                "Write only points with a label other than 0."};

bool finite(const cv::Vec3f& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

char* put_le32(char* out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i)
    *out++ = static_cast<char>((value >> (8 * i)) & 0xFFU);
  return out;
}

// The shortest text that reads back as the same float.
void append_float(std::string& out, float value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_uint(std::string& out, std::uint32_t value) {
  char buffer[16];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

// Calls visit(point, label) for every point that goes into the file, in row-major order.
template <class Visit>
void for_each_vertex(const cv::Mat& points, const cv::Mat& labels, bool labelled_only,
                     Visit visit) {
  for (int y = 0; y < points.rows; ++y) {
    const auto* p = points.ptr<cv::Vec3f>(y);
    const std::int32_t* ids = labels.empty() ? nullptr : labels.ptr<std::int32_t>(y);
    for (int x = 0; x < points.cols; ++x) {
      const std::int32_t id = ids != nullptr ? ids[x] : 0;
      if (!finite(p[x]) || (labelled_only && id == 0)) continue;
      visit(p[x], static_cast<std::uint32_t>(id));
    }
  }
}

}  // namespace

PlyCloud make_ply(const cv::Mat& points, const cv::Mat& labels, PlyFormat format,
                  bool labelled_only, const std::string& comment) {
  CV_Assert(points.type() == CV_32FC3);
  CV_Assert(labels.empty() || (labels.type() == CV_32SC1 && labels.size() == points.size()));
  PlyCloud cloud;
  for_each_vertex(points, labels, labelled_only,
                  [&](const cv::Vec3f&, std::uint32_t) { ++cloud.vertices; });

  cloud.header = "ply\nformat ";
  cloud.header += format == PlyFormat::ascii ? "ascii" : "binary_little_endian";
  cloud.header += " 1.0\n";
  if (!comment.empty()) cloud.header += "comment " + one_line(comment) + "\n";
  cloud.header += "element vertex " + std::to_string(cloud.vertices) +
                  "\n"
                  "property float x\n"
                  "property float y\n"
                  "property float z\n"
                  "property uchar red\n"
                  "property uchar green\n"
                  "property uchar blue\n"
                  "property uint label\n"
                  "end_header\n";

  // Colours are looked up once per run of equal ids.
  std::uint32_t last_id = 0;
  Rgb colour = kUnlabelled;
  const auto colour_of = [&](std::uint32_t id) {
    if (id != last_id) {
      last_id = id;
      colour = id == 0 ? kUnlabelled : label_colour(id);
    }
    return colour;
  };

  if (format == PlyFormat::binary_little_endian) {
    cloud.body.resize(static_cast<std::size_t>(cloud.vertices) * kBinaryVertexBytes);
    char* out = cloud.body.data();
    for_each_vertex(points, labels, labelled_only, [&](const cv::Vec3f& p, std::uint32_t id) {
      for (int i = 0; i < 3; ++i)
        out = put_le32(out, std::bit_cast<std::uint32_t>(p[i]));
      const Rgb c = colour_of(id);
      *out++ = static_cast<char>(c.r);
      *out++ = static_cast<char>(c.g);
      *out++ = static_cast<char>(c.b);
      out = put_le32(out, id);
    });
    return cloud;
  }
  cloud.body.reserve(static_cast<std::size_t>(cloud.vertices) * 40);
  for_each_vertex(points, labels, labelled_only, [&](const cv::Vec3f& p, std::uint32_t id) {
    for (int i = 0; i < 3; ++i) {
      append_float(cloud.body, p[i]);
      cloud.body += ' ';
    }
    const Rgb c = colour_of(id);
    for (const std::uint8_t channel : {c.r, c.g, c.b}) {
      append_uint(cloud.body, channel);
      cloud.body += ' ';
    }
    append_uint(cloud.body, id);
    cloud.body += '\n';
  });
  return cloud;
}

StageSpec CloudSink::spec() {
  StageSpec spec("io.cloud",
                 "Writes each frame's valid 3D points as <dir>/<stem>.ply with a segment id "
                 "and colour per point.\n"
                 "One vertex per finite point (NaN points are skipped), in row-major pixel "
                 "order: float x, y, z in metres in the camera frame (x right, y down, z along "
                 "the optical axis), uchar red, green, blue (the segment's colour, the same as "
                 "io.overlay's; light grey 170 for label 0) and uint label. Binary little-"
                 "endian by default, ascii on request. Opens in MeshLab, CloudCompare and "
                 "Open3D; format: docs/data-formats.md. About 19 bytes per point in binary.");
  return spec.declare(kPoints, kLabels, kDir, kFormat, kLabelledOnly)
      .concurrency(Concurrency::serial);
}

CloudSink::CloudSink(const Params& params)
    : dir_(kDir(params)), format_(kFormat(params)), labelled_only_(kLabelledOnly(params)) {}

void CloudSink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_);
  earlier_ = EarlierResults::survey(dir_, ".ply");
}

void CloudSink::process(ProcessContext& ctx) {
  earlier_.warn_once(ctx);
  const PointImage& points = kPoints(ctx);
  const std::filesystem::path file =
      std::filesystem::path(frame_file(dir_, points.frame)).replace_extension(".ply");
  cv::Mat ids;  // CV_32SC1 with ids of 0 or more (LabelImage's format), so PLY's unsigned labels
  if (const LabelImage* labels = kLabels(ctx); labels != nullptr) {
    require_same_size(points.points, "points", labels->labels, "labels");
    ids = labels->labels;
  }
  const std::string comment =
      "facet io.cloud, frame " +
      (points.frame.stem.empty() ? std::to_string(points.frame.index) : points.frame.stem) +
      ": metres, camera frame (x right, y down, z forward)";
  const PlyCloud cloud = make_ply(points.points, ids, format_, labelled_only_, comment);
  write_file_atomically(file, {cloud.header, cloud.body});
  ctx.metric("points", static_cast<double>(cloud.vertices));
}

}  // namespace facet::io
