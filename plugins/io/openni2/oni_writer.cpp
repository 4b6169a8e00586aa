#include "openni2/oni_writer.hpp"

#include <array>
#include <bit>
#include <cstring>
#include <string>
#include <utility>

#include "facet/error.hpp"

namespace facet::openni2 {
namespace {

// Record types and constants of OpenNI's recording format, as its file driver reads them.
enum RecordType : std::uint32_t {
  kIntProperty = 0x03,
  kGeneralProperty = 0x06,
  kNodeDataBegin = 0x08,
  kNodeStateReady = 0x09,
  kNewData = 0x0A,
  kEnd = 0x0B,
  kNodeAdded = 0x0D,
};
constexpr std::uint32_t kRecordMagic = 0x0052494E;  // "NIR\0"
constexpr std::int32_t kDepthNodeType = 2;
constexpr std::uint32_t kNodeId = 0;
constexpr std::uint32_t kPixelFormatDepth1mm = 100;
// Codec ids are four characters, the first in the lowest byte; "NONE" = uncompressed.
constexpr std::uint32_t kCodecUncompressed = 'N' | ('O' << 8) | ('N' << 16) | ('E' << 24);
constexpr std::size_t kRecordHeaderBytes = 28;  // magic, type, node, fields size, payload, undo
// The player's frame buffer: 1600 x 1200 pixels of 3 bytes.
constexpr std::uint64_t kMaxFrameBytes = 1600ULL * 1200ULL * 3ULL;

// Little-endian fields, appended to a record being built.
class Fields {
 public:
  void u16(std::uint16_t v) { bytes(&v, sizeof(v)); }
  void u32(std::uint32_t v) { bytes(&v, sizeof(v)); }
  void i32(std::int32_t v) { bytes(&v, sizeof(v)); }
  void u64(std::uint64_t v) { bytes(&v, sizeof(v)); }
  void f64(double v) { bytes(&v, sizeof(v)); }
  // A string is its length with the terminating NUL, then its characters and the NUL.
  void text(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size() + 1));
    data_.append(s);
    data_.push_back('\0');
  }
  void bytes(const void* p, std::size_t n) { data_.append(static_cast<const char*>(p), n); }
  const std::string& data() const { return data_; }

 private:
  std::string data_;
};
static_assert(std::endian::native == std::endian::little, "the .oni format is little-endian");

std::string record(RecordType type, const Fields& fields, std::uint32_t payload_bytes = 0) {
  Fields header;
  header.u32(kRecordMagic);
  header.u32(type);
  header.u32(kNodeId);
  header.u32(static_cast<std::uint32_t>(kRecordHeaderBytes + fields.data().size()));
  header.u32(payload_bytes);
  header.u64(0);  // no undo record: the recording never changes a property
  return header.data() + fields.data();
}

std::string general_property(const std::string& name, const Fields& value) {
  Fields fields;
  fields.text(name);
  fields.u32(static_cast<std::uint32_t>(value.data().size()));
  fields.bytes(value.data().data(), value.data().size());
  return record(kGeneralProperty, fields);
}

std::string int_property(const std::string& name, std::uint64_t value) {
  Fields fields;
  fields.text(name);
  fields.u32(sizeof(value));
  fields.u64(value);
  return record(kIntProperty, fields);
}

}  // namespace

OniDepthWriter::OniDepthWriter(std::filesystem::path file, const OniStreamInfo& info)
    : file_(std::move(file)), info_(info) {
  if (info.width_px <= 0 || info.height_px <= 0 || info.fps <= 0) {
    fail("a depth stream needs a size and an fps > 0");
  }
  if (static_cast<std::uint64_t>(info.width_px) * static_cast<std::uint64_t>(info.height_px) * 2 >
      kMaxFrameBytes) {
    fail(std::to_string(info.width_px) + "x" + std::to_string(info.height_px) +
         " is larger than OpenNI2's player reads (1600x1200 pixels of depth at most)");
  }
  out_.open(file_, std::ios::binary | std::ios::trunc);
  if (!out_) fail("cannot create the file");

  // File header: magic, format version 1.0.1.0, largest timestamp, largest node id.
  Fields header;
  header.bytes("NI10", 4);
  header.bytes(std::array<std::uint8_t, 2>{1, 0}.data(), 2);
  header.u16(1);
  header.u32(0);
  global_max_pos_ = static_cast<std::streamoff>(header.data().size());
  header.u64(0);  // patched by finish()
  header.u32(kNodeId);
  out_ << header.data();

  // The depth node: name, type, codec, then frames and time range (patched), no seek table.
  Fields node;
  node.text("Depth");
  node.i32(kDepthNodeType);
  node.u32(kCodecUncompressed);
  const std::size_t counts_offset = node.data().size();
  node.u32(0);
  node.u64(0);
  node.u64(0);
  node.u64(0);
  node_frames_pos_ =
      static_cast<std::streamoff>(header.data().size() + kRecordHeaderBytes + counts_offset);
  out_ << record(kNodeAdded, node);

  // Its state: output mode (size, fps), pixel format, frame size, field of view, no cropping.
  Fields mode;
  mode.u32(static_cast<std::uint32_t>(info.width_px));
  mode.u32(static_cast<std::uint32_t>(info.height_px));
  mode.u32(static_cast<std::uint32_t>(info.fps));
  out_ << general_property("xnMapOutputMode", mode);
  out_ << int_property("oniPixelFormat", kPixelFormatDepth1mm);
  out_ << int_property("RequiredDataSize", static_cast<std::uint64_t>(info.width_px) *
                                               static_cast<std::uint64_t>(info.height_px) * 2);
  out_ << int_property("xnDeviceMaxDepth", 65535);
  Fields fov;
  fov.f64(info.hfov_rad);
  fov.f64(info.vfov_rad);
  out_ << general_property("xnFOV", fov);
  Fields cropping;  // enabled (a 32-bit boolean), x, y, width, height
  cropping.u32(0);
  for (int i = 0; i < 4; ++i)
    cropping.u16(0);
  out_ << general_property("xnCropping", cropping);
  out_ << record(kNodeStateReady, Fields());

  Fields begin;  // frames and largest timestamp, patched
  begin.u32(0);
  begin.u64(0);
  data_begin_pos_ =
      static_cast<std::streamoff>(out_.tellp()) + static_cast<std::streamoff>(kRecordHeaderBytes);
  out_ << record(kNodeDataBegin, begin);
  if (!out_) fail("write error");
}

OniDepthWriter::~OniDepthWriter() {
  if (finished_) return;
  try {
    finish();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
  }
}

void OniDepthWriter::fail(const std::string& what) const {
  throw StageError("cannot write recording '" + file_.string() + "': " + what);
}

void OniDepthWriter::add(const cv::Mat& depth_mm, std::uint64_t timestamp_us) {
  if (finished_) fail("add() after finish()");
  if (depth_mm.type() != CV_16UC1 || depth_mm.cols != info_.width_px ||
      depth_mm.rows != info_.height_px) {
    fail("frame " + std::to_string(frames_ + 1) + " is not CV_16UC1 of " +
         std::to_string(info_.width_px) + "x" + std::to_string(info_.height_px));
  }
  if (frames_ > 0 && timestamp_us < last_us_) fail("timestamps must not decrease");
  const std::size_t row_bytes = static_cast<std::size_t>(depth_mm.cols) * 2;
  Fields fields;
  fields.u64(timestamp_us);
  fields.u32(frames_ + 1);  // frame numbers count from 1
  out_ << record(kNewData, fields, static_cast<std::uint32_t>(row_bytes * depth_mm.rows));
  for (int y = 0; y < depth_mm.rows; ++y)
    out_.write(depth_mm.ptr<char>(y), static_cast<std::streamsize>(row_bytes));
  if (!out_) fail("write error");
  if (frames_ == 0) first_us_ = timestamp_us;
  last_us_ = timestamp_us;
  ++frames_;
}

void OniDepthWriter::finish() {
  if (finished_) return;
  finished_ = true;
  out_ << record(kEnd, Fields());
  const auto patch = [this](std::streamoff position, const Fields& fields) {
    out_.seekp(position);
    out_ << fields.data();
  };
  Fields global;
  global.u64(last_us_);
  patch(global_max_pos_, global);
  Fields node;
  node.u32(frames_);
  node.u64(first_us_);
  node.u64(last_us_);
  patch(node_frames_pos_, node);
  Fields begin;
  begin.u32(frames_);
  begin.u64(last_us_);
  patch(data_begin_pos_, begin);
  out_.close();
  if (!out_) fail("write error");
}

}  // namespace facet::openni2
