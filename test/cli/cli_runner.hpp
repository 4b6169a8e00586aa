#pragma once
// Runs the facet CLI as a user would and captures what it printed and its exit code.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "temp_dir.hpp"

namespace facet::test {

struct CliResult {
  int exit_code = -1;
  std::string out;  // stdout and stderr, interleaved as printed
};

inline std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

// `arguments` is appended to the command line as written (quote paths with shell_quote).
inline CliResult run_cli(const std::string& arguments, const std::string& environment = "") {
  const std::string command =
      environment + " " + shell_quote(FACET_CLI) + " " + arguments + " 2>&1";
  CliResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// The same, run from folder `dir`: relative paths in `arguments` are relative to it.
inline CliResult run_cli_in(const std::filesystem::path& dir, const std::string& arguments) {
  return run_cli(arguments, "cd " + shell_quote(dir.string()) + " &&");
}

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::filesystem::path source_dir() {
  return FACET_SOURCE_DIR;
}

}  // namespace facet::test
