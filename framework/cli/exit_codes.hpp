#pragma once

namespace facet::cli {

// Documented in `facet --help`; scripts rely on them.
enum ExitCode : int {
  kOk = 0,
  kRuntimeFailure = 1,  // a stage failed while the graph ran (bad file, bad input, ...)
  kUsage = 2,           // wrong command line, unknown stage name given to inspect
  kInvalidGraph = 3,    // the graph file has errors (all are printed)
  kPluginFailure = 4,   // a plugin needed by the graph (or asked for by doctor) failed to load
};

}  // namespace facet::cli
