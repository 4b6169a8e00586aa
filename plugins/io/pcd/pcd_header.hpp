#pragma once
// The header of a PCD file, parsed and checked against the file's size before PCL reads it.
//
// PCL 1.13's reader trusts its header: a negative or oversized COUNT or SIZE, a
// binary_compressed cloud whose uncompressed size is 0 or huge, or POINTS far beyond what the
// file holds make it crash, loop for billions of iterations or allocate gigabytes. Every such
// header is refused here, naming the file and the field, so PCL only ever sees consistent ones.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace facet::pcd {

// The largest cloud read: 2^26 points (an 8192 x 8192 organized cloud).
inline constexpr std::uint64_t kMaxPcdPoints = std::uint64_t{1} << 26;
// The most fields, and the most values one field may have (COUNT), in a header.
inline constexpr std::size_t kMaxPcdFields = 256;
inline constexpr std::uint64_t kMaxPcdFieldCount = 4096;

enum class PcdEncoding { ascii, binary, binary_compressed };

struct PcdField {
  std::string name;
  int size_bytes = 0;  // 1, 2, 4 or 8
  char type = 'F';     // I, U or F
  std::uint64_t count = 1;
};

struct PcdHeader {
  std::vector<PcdField> fields;
  std::uint64_t width = 0;
  std::uint64_t height = 0;
  std::uint64_t points = 0;
  PcdEncoding encoding = PcdEncoding::ascii;
  std::uint64_t header_bytes = 0;  // up to and including the DATA line's newline

  std::uint64_t point_bytes() const;
};

// Parses the header of `text` (the file's first bytes; it must hold the whole header) and
// checks it for consistency: FIELDS, SIZE, TYPE and COUNT of the same length with valid
// entries, WIDTH x HEIGHT = POINTS (at most kMaxPcdPoints). `what` names the file in errors.
// Throws facet::StageError.
PcdHeader parse_pcd_header(const std::string& text, const std::string& what);

// Checks that a file of `file_bytes` can hold the data `header` declares: the binary data in
// full; for binary_compressed, the two sizes in front of the data (`size_words`: the 8 bytes
// after the header, or fewer when the file ends) against the file and the declared points; for
// ascii, at least one character and one separator per value. Throws facet::StageError.
void check_pcd_data_size(const PcdHeader& header, std::uint64_t file_bytes,
                         const std::string& size_words, const std::string& what);

// Both checks on a file on disk.
PcdHeader check_pcd_file(const std::filesystem::path& file);

}  // namespace facet::pcd
