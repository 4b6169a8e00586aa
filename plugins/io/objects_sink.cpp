#include "io/objects_sink.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string_view>

#include "facet/contract.hpp"
#include "io/output_folder.hpp"

namespace facet::io {
namespace {

// A minimal JSON writer: objects and arrays with fixed key order, one value per line except for
// short numeric arrays. Plugins do not link the framework, which has its own writer.
class JsonText {
 public:
  void open_object(std::string_view key = {}) { open(key, '{'); }
  void open_array(std::string_view key = {}) { open(key, '['); }
  void close_object() { close('}'); }
  void close_array() { close(']'); }

  void number(std::string_view key, double value) { item(key, format_number(value)); }
  void integer(std::string_view key, long long value) { item(key, std::to_string(value)); }
  void boolean(std::string_view key, bool value) { item(key, value ? "true" : "false"); }
  void string(std::string_view key, std::string_view value) { item(key, quote(value)); }
  void null(std::string_view key) { item(key, "null"); }
  template <class Vector>
  void numbers(std::string_view key, const Vector& values) {
    std::string text = "[";
    for (Eigen::Index i = 0; i < values.size(); ++i) {
      if (i > 0) text += ", ";
      text += format_number(values[i]);
    }
    item(key, text + "]");
  }

  std::string finish() { return std::move(text_) + "\n"; }

 private:
  static std::string format_number(double value) {
    if (!std::isfinite(value)) return "null";  // JSON has no NaN or infinity
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
  }
  static std::string quote(std::string_view value) {
    std::string out = "\"";
    for (const char c : value) {
      switch (c) {
        case '"':
          out += "\\\"";
          break;
        case '\\':
          out += "\\\\";
          break;
        case '\n':
          out += "\\n";
          break;
        case '\r':
          out += "\\r";
          break;
        case '\t':
          out += "\\t";
          break;
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
            out += escaped;
          } else {
            out += c;
          }
      }
    }
    return out + "\"";
  }
  void item(std::string_view key, std::string_view value) {
    separate();
    if (!key.empty()) text_ += quote(key) + ": ";
    text_ += value;
  }
  void open(std::string_view key, char bracket) {
    item(key, std::string_view(&bracket, 1));
    first_ = true;
    ++depth_;
  }
  void close(char bracket) {
    --depth_;
    text_ += '\n';
    text_.append(2 * static_cast<std::size_t>(depth_), ' ');
    text_ += bracket;
    first_ = false;
  }
  void separate() {
    if (depth_ == 0) return;
    if (!first_) text_ += ',';
    text_ += '\n';
    text_.append(2 * static_cast<std::size_t>(depth_), ' ');
    first_ = false;
  }

  std::string text_;
  int depth_ = 0;
  bool first_ = true;
};

const In<ObjectList> kObjects{"objects",
                              "Per-object shape models (shape.superquadric, shape.pca_box)."};
const Param<std::string> kDir{
    "dir", "out/objects", "Output folder, created if missing.", {.required = true}};

std::filesystem::path json_file(const std::filesystem::path& dir, const FrameInfo& frame) {
  return std::filesystem::path(frame_file(dir, frame)).replace_extension(".json");
}

void write_camera(JsonText& json, const CameraIntrinsics& camera) {
  if (!camera.valid()) {  // a list made without a camera (a test, a program's own list)
    json.null("camera");
    return;
  }
  json.open_object("camera");
  json.number("fx", camera.fx);
  json.number("fy", camera.fy);
  json.number("cx", camera.cx);
  json.number("cy", camera.cy);
  json.integer("width", camera.width);
  json.integer("height", camera.height);
  json.close_object();
}

}  // namespace

std::string objects_to_json(const ObjectList& list) {
  JsonText json;
  json.open_object();
  json.integer("schema_version", kObjectsJsonSchemaVersion);
  json.open_object("frame");
  json.string("stem", list.frame.stem);
  json.integer("index", list.frame.index);
  json.integer("timestamp_ns", list.frame.timestamp_ns);
  json.close_object();
  write_camera(json, list.camera);
  json.open_array("objects");
  for (const ObjectModel& object : list.objects)
    write_object(json, object);
  json.close_array();
  json.close_object();
  return json.finish();
}

StageSpec ObjectsSink::spec() {
  StageSpec spec("io.objects",
                 "Writes each frame's object list as <dir>/<stem>.json.\n"
                 "One file per frame (frame_<index>.json without a stem): schema version, "
                 "frame stem, index and timestamp, the camera intrinsics, and per object its "
                 "id, pixel count, centroid, axis-aligned bounds, oriented box, support plane "
                 "id and equation, superquadric and grasp prototype, in metres in the camera "
                 "frame. Schema: docs/objects-json.md. Deterministic "
                 "formatting, so equal lists give equal files.");
  return spec.declare(kObjects, kDir).concurrency(Concurrency::serial);
}

ObjectsSink::ObjectsSink(const Params& params) : dir_(kDir(params)) {}

void ObjectsSink::open(const OpenContext& /*ctx*/) {
  ensure_folder(dir_);
  earlier_ = EarlierResults::survey(dir_, ".json");
}

void ObjectsSink::process(ProcessContext& ctx) {
  earlier_.warn_once(ctx);
  if (kObjects.packet(ctx).empty()) return;
  const ObjectList& list = kObjects(ctx);
  const std::filesystem::path file = json_file(dir_, list.frame);
  const std::string text = objects_to_json(list);
  write_file_atomically(file, {text});
}

}  // namespace facet::io
