#include "partition/patch_graph_sink.hpp"

#include <fstream>
#include <string>
#include <system_error>

#include "facet/contract.hpp"
#include "partition/patch_graph.hpp"

namespace facet::partition {
namespace {

const In<PatchGraph> kGraph{"graph", "partition.graph's graph output."};
const Param<std::string> kDir{
    "dir", "out/graph", "Output folder, created if missing.", {.required = true}};

}  // namespace

StageSpec PatchGraphSink::spec() {
  return StageSpec("io.patch_graph",
                   "Writes partition.graph's surface-patch graph as <dir>/<stem>.json.\n"
                   "One file per frame (frame_<index>.json without a stem): the nodes (blob, "
                   "patch, object, size, planar, plane residual, mean pixel, normal, centroid) "
                   "and the edges (node indices, the feature that made the edge, whether the cut "
                   "kept it). For a person to look at; partition.graph fills its graph output "
                   "only with emit_graph: true.")
      .declare(kGraph, kDir)
      .concurrency(Concurrency::serial);
}

PatchGraphSink::PatchGraphSink(const Params& params) : dir_(kDir(params)) {}

void PatchGraphSink::open(const OpenContext& /*ctx*/) {
  std::error_code error;
  std::filesystem::create_directories(dir_, error);
  if (error) throw StageError("cannot create '" + dir_.string() + "': " + error.message());
}

void PatchGraphSink::process(ProcessContext& ctx) {
  if (kGraph.packet(ctx).empty()) return;
  const auto& graph = kGraph(ctx);
  const std::string name =
      graph.frame.stem.empty() ? "frame_" + std::to_string(graph.frame.index) : graph.frame.stem;
  const std::filesystem::path file = dir_ / (name + ".json");
  const std::string text = patch_graph_json(graph);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw StageError("cannot open '" + file.string() + "' for writing");
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw StageError("cannot write '" + file.string() + "'");
}

}  // namespace facet::partition
