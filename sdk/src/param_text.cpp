#include "facet/param_text.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>

namespace facet {
namespace {

constexpr std::string_view kSpaces = " \t\n\r\f\v";

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(kSpaces);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kSpaces) - first + 1);
}

// The stream's float reading (what the parameters were parsed with before they had a type), so
// every value keeps exactly the float it had.
std::optional<float> parse_number(std::string_view field) {
  std::istringstream in{std::string(field)};
  float value = 0.0F;
  in >> value;
  if (in.fail() || !(in >> std::ws).eof() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

std::variant<NumberList, std::string> parse_number_list(std::string_view text, std::size_t count) {
  std::vector<std::string_view> raw_fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    raw_fields.push_back(
        text.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (raw_fields.size() != count) {
    return std::to_string(count) + " comma-separated numbers are needed, not " +
           std::to_string(raw_fields.size());
  }
  NumberList list;
  for (const std::string_view field : raw_fields) {
    const std::optional<float> value = parse_number(field);
    if (!value) {
      std::string why = "'";
      why.append(trimmed(field));
      why.append("' is not a finite number");
      return why;
    }
    list.values.push_back(*value);
    list.fields.push_back(trimmed(field));
  }
  return list;
}

std::string format_number_list(std::span<const float> values) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ",";
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, values[i]);
    text.append(buffer, result.ptr);
  }
  return text;
}

}  // namespace facet
