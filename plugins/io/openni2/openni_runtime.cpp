#include "openni2/openni_runtime.hpp"

#include <OpenNI.h>

#include <cstddef>
#include <mutex>

#include "facet/error.hpp"

namespace facet::openni2 {
namespace {

// The holders of OpenNI2's own process-wide state. This function-local static mirrors that
// global of the library (it is not state of ours): one count of users per process, guarded so
// that initialise and shutdown never interleave.
struct RuntimeUsers {
  std::mutex mutex;
  std::size_t count = 0;
};

RuntimeUsers& runtime_users() {
  static RuntimeUsers users;
  return users;
}

}  // namespace

std::shared_ptr<const OpenNiRuntime> OpenNiRuntime::acquire() {
  RuntimeUsers& users = runtime_users();
  const std::lock_guard lock(users.mutex);
  if (users.count == 0) {
    if (openni::OpenNI::initialize() != openni::STATUS_OK) {
      const std::string reason = openni_last_error();
      openni::OpenNI::shutdown();  // initialize() may have loaded some drivers before it failed
      throw StageError("OpenNI2 could not be initialised: " + reason);
    }
  }
  ++users.count;
  // The deleter, not a destructor, gives the library back: it runs under the same lock.
  return std::shared_ptr<const OpenNiRuntime>(new OpenNiRuntime(), [](const OpenNiRuntime* p) {
    delete p;
    RuntimeUsers& owners = runtime_users();
    const std::lock_guard release_lock(owners.mutex);
    if (--owners.count == 0) openni::OpenNI::shutdown();
  });
}

std::string OpenNiRuntime::version() const {
  const openni::Version v = openni::OpenNI::getVersion();
  return std::to_string(v.major) + "." + std::to_string(v.minor) + "." +
         std::to_string(v.maintenance) + "." + std::to_string(v.build);
}

std::string openni_last_error() {
  const char* raw = openni::OpenNI::getExtendedError();
  std::string text = raw != nullptr ? raw : "";
  // OpenNI2 indents each message with a tab and ends it with a newline; several may be joined.
  std::string line;
  bool space = false;
  for (const char c : text) {
    if (c == '\t' || c == '\n' || c == '\r' || c == ' ') {
      space = !line.empty();
      continue;
    }
    if (space) line += ' ';
    space = false;
    line += c;
  }
  return line.empty() ? "no details" : line;
}

}  // namespace facet::openni2
