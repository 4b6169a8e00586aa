// A TUM RGB-D association list (timestamps, paths, comments) as io.frames lists it. The paths
// it names need not exist: listing is what is fuzzed. An exception is a refusal; a crash, a
// hang or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>

#include "io/frame_listing.hpp"
#include "scratch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = facet::fuzz::scratch().write("associations.txt", std::span(data, size));
  try {
    (void)facet::io::list_frames(file.string());
  } catch (const std::exception&) {
  }
  std::int64_t nanoseconds = 0;
  (void)facet::io::parse_seconds(std::string(reinterpret_cast<const char*>(data), size),
                                 nanoseconds);
  return 0;
}
