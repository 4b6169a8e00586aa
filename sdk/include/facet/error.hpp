#pragma once

#include <stdexcept>
#include <string>

namespace facet {

// Thrown by a stage for a problem with its input or configuration that the user can fix.
// The executor adds the node id, stage name and frame to the message.
class StageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace facet
