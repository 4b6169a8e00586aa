// The PCD header check that stands between a downloaded cloud and PCL's reader: parsed from the
// input's bytes, then checked against a file size and the data words taken from the input too.
// An exception is a refusal; a crash, a hang or a sanitizer report is a finding.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "pcd/pcd_header.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const facet::pcd::PcdHeader header = facet::pcd::parse_pcd_header(text, "fuzz.pcd");
    const std::size_t after = std::min<std::size_t>(header.header_bytes, text.size());
    const std::string size_words = text.substr(after, 8);
    facet::pcd::check_pcd_data_size(header, text.size(), size_words, "fuzz.pcd");
  } catch (const std::exception&) {
  }
  return 0;
}
