#pragma once
// io.objects: writes each frame's object list as <dir>/<stem>.json (schema: docs/objects-json.md).

#include <filesystem>
#include <string>

#include "facet/stage.hpp"
#include "facet/types/geometry.hpp"
#include "io/output_folder.hpp"

namespace facet::io {

class ObjectsSink final : public Stage {
 public:
  static StageSpec spec();
  explicit ObjectsSink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
  EarlierResults earlier_;  // what the folder held before this run
};

// The file's "schema_version". 1 (files without the field): frame and objects only. 2: the
// frame's "camera" intrinsics and each object's "support_plane_equation".
inline constexpr int kObjectsJsonSchemaVersion = 2;

// The JSON text io.objects writes for one frame: deterministic (fixed key order, numbers with
// 9 significant digits, 2-space indentation), ending in a newline.
std::string objects_to_json(const ObjectList& list);

}  // namespace facet::io
