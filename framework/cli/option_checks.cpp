#include "option_checks.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

namespace facet::cli {
namespace {

bool parse_integer(const std::string& text, std::int64_t& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && ptr == end;
}

CLI::Validator integer_at_least(std::int64_t minimum, const std::string& what) {
  return CLI::Validator(
      [minimum, what](std::string& text) -> std::string {
        std::int64_t value = 0;
        if (!parse_integer(text, value) || value < minimum) {
          return "must be " + what + ", got '" + text + "'";
        }
        return {};
      },
      what == "a positive integer" ? "INT>0" : "INT>=0");
}

}  // namespace

CLI::Validator non_negative_integer() {
  return integer_at_least(0, "a non-negative integer");
}

CLI::Validator positive_integer() {
  return integer_at_least(1, "a positive integer");
}

CLI::Validator non_negative_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::size_t used = 0;
        double value = 0.0;
        try {
          value = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(value) || value < 0.0) {
          return "must be a non-negative number, got '" + text + "'";
        }
        return {};
      },
      "NUMBER>=0");
}

}  // namespace facet::cli
