#pragma once
// What CLI11 leaves terse: `facet help [COMMAND]`, an unknown command ("frobnicate") and an
// unknown option ("--frmes") get an answer that names them, with the closest known spelling.

#include <CLI/CLI.hpp>
#include <optional>

namespace facet::cli {

// Before parsing: handles `facet help [COMMAND]` and an unknown command word. Returns the exit
// code when it has answered, nothing when the command line is for CLI11 to parse.
std::optional<int> answer_command_word(CLI::App& app, int argc, char** argv);

// After CLI11 refused unexpected arguments: names each unknown option of the command with a
// suggestion. Returns false when no argument looked like an option (CLI11's message stands).
bool explain_unknown_options(CLI::App& app, int argc, char** argv);

}  // namespace facet::cli
