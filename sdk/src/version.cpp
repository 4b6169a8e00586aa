#include "facet/version.hpp"

namespace facet {

const char* sdk_toolchain_fingerprint() noexcept {
  return FACET_TOOLCHAIN_FINGERPRINT;
}

}  // namespace facet
