#pragma once
// Whether a window can be opened, asked before OpenCV's highgui is touched: Debian's highgui
// draws with Qt on X11, and Qt aborts the whole process when it cannot reach the display.

#include <memory>
#include <optional>
#include <string>

namespace facet::view {

struct DisplayCheck {
  // Nothing when a window can be opened; otherwise why not, for a person, e.g. "no display:
  // DISPLAY and WAYLAND_DISPLAY are unset".
  std::optional<std::string> problem;
  // The connection the check made to the X server, for the caller to hold while its window
  // lives: an X server resets when its last client leaves, and a window opened during that
  // reset fails (Qt then aborts). Empty when there is no X connection to hold.
  std::shared_ptr<void> connection;
};

// Reads DISPLAY, WAYLAND_DISPLAY and QT_QPA_PLATFORM; with DISPLAY set, connects to the X server
// (libxcb) to see that it answers.
DisplayCheck check_display();

// check_display().problem, the connection closed again.
std::optional<std::string> why_no_display();

}  // namespace facet::view
