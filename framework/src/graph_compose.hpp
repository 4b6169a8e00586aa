#pragma once
// Graph composition: a graph file with `extends: BASE.yaml` starts from the base's params,
// nodes, graph ports, variants and headline, then applies its own `remove:`, `replace:` and
// `set:` to the base's nodes and adds its own nodes, params and variants; its own headline, when
// it names one, replaces the base's. A chain of such files is folded from the last base up, so
// that each file edits what the files below it made.

#include <filesystem>
#include <functional>
#include <optional>

#include "facet/framework/diagnostics.hpp"
#include "graph_document.hpp"

namespace facet::detail {

// Reads and parses the graph file `file`; `requested_at` is the `extends:` that names it, where
// a file that cannot be read is reported. Nothing when it is not a graph (reported).
using BaseGraphReader = std::function<std::optional<RawGraph>(const std::filesystem::path& file,
                                                              const SourceLocation& requested_at)>;

// The absolute folder of a graph file: what ${graph_dir} and its relative paths refer to.
std::filesystem::path absolute_dir_of(const std::filesystem::path& file);

// Replaces `graph` (read from `file`) by its composition with its bases. Without `extends:` the
// graph stays as it is.
void resolve_extends(RawGraph& graph, const std::filesystem::path& file,
                     const BaseGraphReader& read_base, Diagnostics& diagnostics);

}  // namespace facet::detail
