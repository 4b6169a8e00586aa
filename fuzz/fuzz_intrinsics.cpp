// intrinsics.yaml as a downloaded dataset brings it, read by the reader io.frames uses. An
// exception is a refusal; a crash, a hang or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>

#include "io/intrinsics_file.hpp"
#include "scratch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = facet::fuzz::scratch().write("intrinsics.yaml", std::span(data, size));
  try {
    (void)facet::io::read_intrinsics(file);
  } catch (const std::exception&) {
  }
  return 0;
}
