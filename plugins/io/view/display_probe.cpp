#include "view/display_probe.hpp"

#include <cstdlib>

#ifdef FACET_VIEW_HAVE_XCB
#include <xcb/xcb.h>
#endif

namespace facet::view {
namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

}  // namespace

DisplayCheck check_display() {
  DisplayCheck check;
  // A platform chosen explicitly (wayland, offscreen, ...) is the user's decision: Qt is told
  // where to draw, and reports its own errors.
  if (!environment("QT_QPA_PLATFORM").empty()) return check;
  const std::string display = environment("DISPLAY");
  if (display.empty()) {
    if (!environment("WAYLAND_DISPLAY").empty()) {
      check.problem =
          "WAYLAND_DISPLAY is set but DISPLAY is not: OpenCV's window draws through X11 "
          "(XWayland); set DISPLAY, or QT_QPA_PLATFORM=wayland";
    } else {
      check.problem = "no display: DISPLAY and WAYLAND_DISPLAY are unset";
    }
    return check;
  }
#ifdef FACET_VIEW_HAVE_XCB
  // xcb_disconnect() also frees a connection that failed.
  std::shared_ptr<xcb_connection_t> connection(xcb_connect(display.c_str(), nullptr),
                                               xcb_disconnect);
  if (xcb_connection_has_error(connection.get()) != 0) {
    check.problem = "cannot connect to the X display '" + display + "'";
    return check;
  }
  check.connection = std::move(connection);
#endif
  return check;
}

std::optional<std::string> why_no_display() {
  return check_display().problem;
}

}  // namespace facet::view
