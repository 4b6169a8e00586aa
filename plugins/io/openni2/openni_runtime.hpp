#pragma once
// OpenNI2 keeps one process-wide state behind OpenNI::initialize() and OpenNI::shutdown(), and
// shutdown() closes every device and stream of every user in the process. OpenNiRuntime is the
// reference-counted owner of that state: the first holder initialises the library, the last one
// to let go shuts it down, so two io.openni2 nodes and `facet doctor` never pull it from under
// each other.

#include <memory>
#include <string>

namespace facet::openni2 {

class OpenNiRuntime {
 public:
  // Initialises OpenNI2 if no one holds it yet. Throws facet::StageError with what OpenNI2
  // reported when it cannot be initialised (e.g. no driver found).
  static std::shared_ptr<const OpenNiRuntime> acquire();

  // The library's version, e.g. "2.2.0.33".
  std::string version() const;

  OpenNiRuntime(const OpenNiRuntime&) = delete;
  OpenNiRuntime& operator=(const OpenNiRuntime&) = delete;

 private:
  OpenNiRuntime() = default;
};

// OpenNI2's last error message (OpenNI::getExtendedError()) on one line, without its tabs and
// trailing newline; "no details" when it is empty.
std::string openni_last_error();

}  // namespace facet::openni2
