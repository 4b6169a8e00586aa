#include "pcd/pcd_header.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>

#include "facet/error.hpp"

namespace facet::pcd {
namespace {

// A header longer than this is not a PCD header (PCL's own files have about 200 bytes).
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
// LZF, the codec of binary_compressed, encodes at most 264 bytes in one 3-byte back reference,
// so no stream inflates by more than a factor of 88.
constexpr std::uint64_t kLzfMaxRatio = 88;

[[noreturn]] void fail(const std::string& what, const std::string& message) {
  throw StageError("PCD file '" + what + "': " + message);
}

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream stream(line);
  std::string word;
  while (stream >> word)
    words.push_back(word);
  return words;
}

std::optional<std::uint64_t> parse_count(const std::string& word) {
  std::uint64_t value = 0;
  const char* end = word.data() + word.size();
  const auto [ptr, error] = std::from_chars(word.data(), end, value);
  if (error != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// A positive integer of at most `max`, or an error naming the entry, the line and the value.
std::uint64_t positive(const std::string& word, std::uint64_t max, const std::string& entry,
                       int line, const std::string& what) {
  const auto value = parse_count(word);
  if (!value || *value == 0 || *value > max) {
    fail(what, "line " + std::to_string(line) + ": " + entry + " '" + word +
                   "' is not an integer from 1 to " + std::to_string(max));
  }
  return *value;
}

struct HeaderLines {
  std::vector<std::string> fields, sizes, types, counts;
  std::optional<std::string> width, height, points, data;
  int width_line = 0, height_line = 0, points_line = 0, sizes_line = 0, types_line = 0,
      counts_line = 0;
};

// The words after the keyword, refusing a second line of the same keyword.
std::vector<std::string> entries(const std::vector<std::string>& words, bool seen, int line,
                                 const std::string& what) {
  if (seen) fail(what, "line " + std::to_string(line) + ": a second " + words[0] + " line");
  return {words.begin() + 1, words.end()};
}

std::string single(const std::vector<std::string>& words, bool seen, int line,
                   const std::string& what) {
  const auto values = entries(words, seen, line, what);
  if (values.size() != 1) {
    fail(what, "line " + std::to_string(line) + ": " + words[0] + " takes one value, not " +
                   std::to_string(values.size()));
  }
  return values[0];
}

void check_lengths(const HeaderLines& lines, const std::string& what) {
  const std::size_t n = lines.fields.size();
  const auto check = [&](const std::vector<std::string>& values, const char* entry, int line) {
    if (values.size() != n) {
      fail(what, "line " + std::to_string(line) + ": " + entry + " has " +
                     std::to_string(values.size()) + " entries for " + std::to_string(n) +
                     " FIELDS");
    }
  };
  check(lines.sizes, "SIZE", lines.sizes_line);
  check(lines.types, "TYPE", lines.types_line);
  if (lines.counts_line != 0) check(lines.counts, "COUNT", lines.counts_line);
}

PcdField field_at(const HeaderLines& lines, std::size_t i, const std::string& what) {
  PcdField field;
  field.name = lines.fields[i];
  const std::string& size = lines.sizes[i];
  const std::string& type = lines.types[i];
  const std::string name = "field '" + field.name + "'";
  if (size != "1" && size != "2" && size != "4" && size != "8") {
    fail(what, "line " + std::to_string(lines.sizes_line) + ": SIZE '" + size + "' of " + name +
                   " is not 1, 2, 4 or 8");
  }
  field.size_bytes = size[0] - '0';
  if (type != "I" && type != "U" && type != "F") {
    fail(what, "line " + std::to_string(lines.types_line) + ": TYPE '" + type + "' of " + name +
                   " is not I, U or F");
  }
  field.type = type[0];
  if (field.type == 'F' && field.size_bytes < 4) {
    fail(what, "line " + std::to_string(lines.sizes_line) + ": " + name +
                   " is a float (TYPE F) of SIZE " + size + " (4 or 8)");
  }
  if (lines.counts_line != 0) {
    field.count =
        positive(lines.counts[i], kMaxPcdFieldCount, "COUNT of " + name, lines.counts_line, what);
  }
  return field;
}

}  // namespace

std::uint64_t PcdHeader::point_bytes() const {
  std::uint64_t bytes = 0;
  for (const PcdField& field : fields)
    bytes += static_cast<std::uint64_t>(field.size_bytes) * field.count;
  return bytes;
}

PcdHeader parse_pcd_header(const std::string& text, const std::string& what) {
  HeaderLines lines;
  PcdHeader header;
  std::size_t begin = 0;
  int line_number = 0;
  while (!lines.data) {
    const std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) {
      fail(what, text.size() >= kMaxHeaderBytes
                     ? "no DATA line in its first " + std::to_string(kMaxHeaderBytes) + " bytes"
                     : "the header ends without a DATA line");
    }
    ++line_number;
    const std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    const auto words = split_words(line);
    if (words.empty() || words[0][0] == '#') continue;
    const std::string& key = words[0];
    if (key == "VERSION" || key == "VIEWPOINT") continue;
    if (key == "FIELDS") {
      lines.fields = entries(words, !lines.fields.empty(), line_number, what);
    } else if (key == "SIZE") {
      lines.sizes = entries(words, lines.sizes_line != 0, line_number, what);
      lines.sizes_line = line_number;
    } else if (key == "TYPE") {
      lines.types = entries(words, lines.types_line != 0, line_number, what);
      lines.types_line = line_number;
    } else if (key == "COUNT") {
      lines.counts = entries(words, lines.counts_line != 0, line_number, what);
      lines.counts_line = line_number;
    } else if (key == "WIDTH") {
      lines.width = single(words, lines.width.has_value(), line_number, what);
      lines.width_line = line_number;
    } else if (key == "HEIGHT") {
      lines.height = single(words, lines.height.has_value(), line_number, what);
      lines.height_line = line_number;
    } else if (key == "POINTS") {
      lines.points = single(words, lines.points.has_value(), line_number, what);
      lines.points_line = line_number;
    } else if (key == "DATA") {
      lines.data = single(words, false, line_number, what);
    } else {
      fail(what, "line " + std::to_string(line_number) + ": '" + key.substr(0, 40) +
                     "' is not a PCD header entry (is this a PCD file?)");
    }
  }
  header.header_bytes = begin;

  if (lines.fields.empty()) fail(what, "the header has no FIELDS line");
  if (lines.fields.size() > kMaxPcdFields) {
    fail(what, std::to_string(lines.fields.size()) + " FIELDS (at most " +
                   std::to_string(kMaxPcdFields) + ")");
  }
  if (lines.sizes_line == 0) fail(what, "the header has no SIZE line");
  if (lines.types_line == 0) fail(what, "the header has no TYPE line");
  check_lengths(lines, what);
  for (std::size_t i = 0; i < lines.fields.size(); ++i)
    header.fields.push_back(field_at(lines, i, what));

  if (!lines.width) fail(what, "the header has no WIDTH line");
  if (!lines.points) fail(what, "the header has no POINTS line");
  header.width = positive(*lines.width, kMaxPcdPoints, "WIDTH", lines.width_line, what);
  header.height =
      lines.height ? positive(*lines.height, kMaxPcdPoints, "HEIGHT", lines.height_line, what) : 1;
  header.points = positive(*lines.points, kMaxPcdPoints, "POINTS", lines.points_line, what);
  if (header.width * header.height != header.points) {
    fail(what, "WIDTH x HEIGHT = " + std::to_string(header.width) + " x " +
                   std::to_string(header.height) + " is not POINTS " +
                   std::to_string(header.points));
  }

  const std::string& data = *lines.data;
  if (data == "ascii") {
    header.encoding = PcdEncoding::ascii;
  } else if (data == "binary") {
    header.encoding = PcdEncoding::binary;
  } else if (data == "binary_compressed") {
    header.encoding = PcdEncoding::binary_compressed;
  } else {
    fail(what, "line " + std::to_string(line_number) + ": DATA '" + data.substr(0, 40) +
                   "' is not ascii, binary or binary_compressed");
  }
  return header;
}

void check_pcd_data_size(const PcdHeader& header, std::uint64_t file_bytes,
                         const std::string& size_words, const std::string& what) {
  const std::uint64_t data_bytes = header.points * header.point_bytes();
  const std::uint64_t available = file_bytes - std::min(file_bytes, header.header_bytes);
  const std::string points = std::to_string(header.points) + " points of " +
                             std::to_string(header.point_bytes()) + " bytes";
  switch (header.encoding) {
    case PcdEncoding::binary:
      if (data_bytes > available) {
        fail(what, "its header declares " + points + " (" + std::to_string(data_bytes) +
                       " bytes of binary data), the file holds " + std::to_string(available));
      }
      return;
    case PcdEncoding::ascii: {
      std::uint64_t values = 0;
      for (const PcdField& field : header.fields)
        values += field.count;
      // Every value takes a character and a separator (the last one's newline may be missing).
      if (header.points * values * 2 - 1 > available) {
        fail(what, "its header declares " + std::to_string(header.points) + " points of " +
                       std::to_string(values) + " values, more than its " +
                       std::to_string(available) + " bytes of ascii data can hold");
      }
      return;
    }
    case PcdEncoding::binary_compressed: {
      if (size_words.size() < 8) {
        fail(what, "it ends before the sizes of its binary_compressed data");
      }
      std::uint32_t compressed = 0;
      std::uint32_t uncompressed = 0;
      std::memcpy(&compressed, size_words.data(), 4);
      std::memcpy(&uncompressed, size_words.data() + 4, 4);
      if (uncompressed != data_bytes) {
        fail(what, "uncompressed size " + std::to_string(uncompressed) + " is not the " +
                       std::to_string(data_bytes) + " bytes of its header's " + points);
      }
      if (compressed == 0 || std::uint64_t{compressed} + 8 > available) {
        fail(what, "compressed size " + std::to_string(compressed) + " does not fit the " +
                       std::to_string(available >= 8 ? available - 8 : 0) +
                       " bytes that follow it");
      }
      if (std::uint64_t{uncompressed} > kLzfMaxRatio * compressed) {
        fail(what, "uncompressed size " + std::to_string(uncompressed) +
                       " is more than LZF can inflate " + std::to_string(compressed) + " bytes to");
      }
      return;
    }
  }
}

PcdHeader check_pcd_file(const std::filesystem::path& file) {
  const std::string what = file.string();
  std::error_code error;
  const std::uint64_t file_bytes = std::filesystem::file_size(file, error);
  if (error) fail(what, "cannot read its size: " + error.message());
  std::ifstream stream(file, std::ios::binary);
  if (!stream) fail(what, "cannot be opened");
  std::string text(std::min<std::uint64_t>(file_bytes, kMaxHeaderBytes), '\0');
  stream.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(stream.gcount()));
  const PcdHeader header = parse_pcd_header(text, what);
  const std::string size_words =
      header.header_bytes < text.size() ? text.substr(header.header_bytes, 8) : std::string();
  std::string words = size_words;
  if (words.size() < 8 && header.header_bytes + 8 <= file_bytes) {
    // The header filled the bytes read: read the size words that follow it.
    stream.clear();
    stream.seekg(static_cast<std::streamoff>(header.header_bytes));
    words.assign(8, '\0');
    stream.read(words.data(), 8);
    words.resize(static_cast<std::size_t>(stream.gcount()));
  }
  check_pcd_data_size(header, file_bytes, words, what);
  return header;
}

}  // namespace facet::pcd
