#pragma once
// One function per subcommand: each adds itself to `app` and, when chosen, stores its exit code
// (see exit_codes.hpp) in `exit_code`.

#include <CLI/CLI.hpp>
#include <string>

namespace facet::cli {

void add_run_command(CLI::App& app, int& exit_code);
void add_validate_command(CLI::App& app, int& exit_code);
void add_list_command(CLI::App& app, int& exit_code);
void add_inspect_command(CLI::App& app, int& exit_code);
void add_dot_command(CLI::App& app, int& exit_code);
void add_doctor_command(CLI::App& app, int& exit_code);
// `command_line`: the whole command as typed, for the report's provenance.
void add_compare_command(CLI::App& app, int& exit_code, std::string command_line);

}  // namespace facet::cli
