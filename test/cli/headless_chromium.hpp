#pragma once
// Headless Chromium as the report tests run it: a throw-away profile, no network, no GPU, and a
// few seconds of virtual time for the page's load handlers.

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_runner.hpp"

namespace facet::test {

inline bool have_chromium() {
  return std::system("command -v chromium > /dev/null 2>&1") == 0;
}

// Loads `page` with its profile in `profile_dir` and writes the DOM after the load to
// `dom_file`; `options` are more of Chromium's (e.g. --screenshot=FILE). The shell's status.
inline int load_in_headless_chromium(const std::filesystem::path& page,
                                     const std::filesystem::path& profile_dir,
                                     const std::filesystem::path& dom_file,
                                     const std::string& options = "") {
  const std::string command =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--user-data-dir=" +
      shell_quote(profile_dir.string()) + " --virtual-time-budget=5000 " + options +
      " --dump-dom " + shell_quote("file://" + page.string()) + " > " +
      shell_quote(dom_file.string()) + " 2> /dev/null";
  return std::system(command.c_str());
}

}  // namespace facet::test
