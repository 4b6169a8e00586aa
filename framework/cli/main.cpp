// facet: run, check and inspect segmentation graphs.

#include <CLI/CLI.hpp>
#include <iostream>

#include "command_words.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "facet/framework/allocator_tuning.hpp"
#include "facet/sdk_version.h"

int main(int argc, char** argv) {
  facet::keep_frame_buffers_mapped();
  facet::share_one_heap_between_threads();
  CLI::App app{
      "facet — model-free 3D scene segmentation from depth images, as YAML graphs of "
      "stage plugins.",
      "facet"};
  app.set_version_flag("--version", std::string("facet ") + FACET_SDK_VERSION_STRING);
  app.require_subcommand(1);
  app.footer(
      "Exit codes:\n"
      "  0  success\n"
      "  1  runtime failure (a stage failed while the graph ran)\n"
      "  2  usage error (bad command line, unknown stage name)\n"
      "  3  invalid graph (every error is printed as file:line:col: error: ...)\n"
      "  4  plugin failure (a needed plugin failed to load; see `facet doctor`)\n"
      "  130, 143  `facet run` stopped by SIGINT (Ctrl-C) or SIGTERM: the frames begun were\n"
      "     finished and written, the statistics too; a second signal ends it at once\n\n"
      "Plugins are searched in --plugin-path, $FACET_PLUGIN_PATH, the graph's plugins.paths,\n"
      "next to the executable (../lib/facet/plugins) and in the install prefix.\n"
      "Run `facet COMMAND --help` for the options of a command.");

  int exit_code = facet::cli::kOk;
  facet::cli::add_run_command(app, exit_code);
  facet::cli::add_validate_command(app, exit_code);
  facet::cli::add_list_command(app, exit_code);
  facet::cli::add_inspect_command(app, exit_code);
  facet::cli::add_dot_command(app, exit_code);
  facet::cli::add_doctor_command(app, exit_code);
  std::string command_line = "facet";
  for (int i = 1; i < argc; ++i)
    command_line += std::string(" ") + argv[i];
  facet::cli::add_compare_command(app, exit_code, std::move(command_line));

  if (const auto answered = facet::cli::answer_command_word(app, argc, argv)) return *answered;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ExtrasError& e) {
    if (facet::cli::explain_unknown_options(app, argc, argv)) return facet::cli::kUsage;
    return app.exit(e) == 0 ? facet::cli::kOk : facet::cli::kUsage;
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? facet::cli::kOk : facet::cli::kUsage;
  }
  return exit_code;
}
