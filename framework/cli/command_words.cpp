#include "command_words.hpp"

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "facet/framework/diagnostics.hpp"

namespace facet::cli {
namespace {

std::vector<CLI::App*> commands_of(CLI::App& app) {
  return app.get_subcommands([](CLI::App*) { return true; });
}

CLI::App* find_command(CLI::App& app, const std::string& name) {
  for (CLI::App* command : commands_of(app)) {
    if (command->get_name() == name) return command;
  }
  return nullptr;
}

std::string command_list(CLI::App& app) {
  std::string list;
  for (CLI::App* command : commands_of(app))
    list += (list.empty() ? "" : ", ") + command->get_name();
  return list;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string best = did_you_mean(word, candidates);
  return best.empty() ? std::string() : "; did you mean '" + best + "'?";
}

}  // namespace

std::optional<int> answer_command_word(CLI::App& app, int argc, char** argv) {
  if (argc < 2) return std::nullopt;
  const std::string word = argv[1];
  if (word.empty() || word.front() == '-') return std::nullopt;
  if (word == "help") {
    if (argc < 3) {
      std::cout << app.help();
      return kOk;
    }
    if (CLI::App* command = find_command(app, argv[2])) {
      std::cout << command->help();
      return kOk;
    }
  } else if (find_command(app, word) != nullptr) {
    return std::nullopt;
  }
  const std::string unknown = word == "help" ? std::string(argv[2]) : word;
  std::vector<std::string> names;
  for (CLI::App* command : commands_of(app))
    names.push_back(command->get_name());
  std::cerr << "error: unknown command '" << unknown << "'" << suggestion(unknown, names)
            << "\ncommands: " << command_list(app)
            << "\nRun `facet --help` for more information.\n";
  return kUsage;
}

bool explain_unknown_options(CLI::App& app, int argc, char** argv) {
  if (argc < 2) return false;
  CLI::App* command = find_command(app, argv[1]);
  if (command == nullptr) return false;
  std::vector<std::string> known;
  for (const CLI::Option* option : command->get_options()) {
    for (const auto& name : option->get_lnames())
      known.push_back("--" + name);
  }
  bool explained = false;
  for (int i = 2; i < argc; ++i) {
    std::string word = argv[i];
    if (word.rfind("--", 0) != 0 || word == "--") continue;
    word = word.substr(0, word.find('='));
    if (std::find(known.begin(), known.end(), word) != known.end()) continue;
    std::cerr << "error: unknown option '" << word << "' of `facet " << command->get_name() << "`"
              << suggestion(word, known) << "\n";
    explained = true;
  }
  if (explained) {
    std::cerr << "Run `facet " << command->get_name() << " --help` for its options.\n";
  }
  return explained;
}

}  // namespace facet::cli
