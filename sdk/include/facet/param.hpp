#pragma once
// Stage parameters: their declaration (ParamSpec) and the validated values a stage is built from.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace facet {

enum class ParamType { boolean, integer, real, string };

std::string_view to_string(ParamType type) noexcept;

using ParamValue = std::variant<bool, std::int64_t, double, std::string>;

// "3", "0.85", "true", "mm" — how a value is written in a graph file and by `facet inspect`.
std::string format_param_value(const ParamValue& value);

// Optional attributes of a parameter, written with designated initialisers:
//   spec.param("size", 3, "Window side length.", {.unit = "px", .choices = {3, 5}});
struct ParamOptions {
  std::string unit = {};                 // "mm", "m", "deg", "px", ... empty for unitless
  std::optional<double> min = {};        // inclusive, integer and real parameters
  std::optional<double> max = {};        // inclusive
  std::vector<ParamValue> choices = {};  // when not empty, the only accepted values
  std::string origin = {};               // where the default comes from: "paper", "measured: ..."
  bool required = false;                 // a graph must set it (the default is only an example)
};

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::string;
  ParamValue default_value;
  std::string doc;
  ParamOptions options;
  // A check beyond type, range and choices, e.g. the parser of a structured value
  // (facet::Param<T> with ParamTraits<T>, facet/contract.hpp): an error message or nothing.
  std::function<std::optional<std::string>(const ParamValue&)> check = {};
};

// Checks `value` against `spec` (type, range, choices, its own check). Returns an error message
// or nothing.
std::optional<std::string> check_param_value(const ParamSpec& spec, const ParamValue& value);

// Parses the text of a graph file or command line ("5", "0.85", "true") as the spec's type.
// Returns the value, or an error message naming the expected type.
std::variant<ParamValue, std::string> parse_param_value(const ParamSpec& spec,
                                                        std::string_view text);

// The validated parameters of one stage instance: every declared parameter has a value.
class Params {
 public:
  Params() = default;
  explicit Params(std::map<std::string, ParamValue, std::less<>> values)
      : values_(std::move(values)) {}

  bool get_bool(std::string_view name) const;
  std::int64_t get_int(std::string_view name) const;
  double get_double(std::string_view name) const;  // accepts integer values too
  const std::string& get_string(std::string_view name) const;

  bool contains(std::string_view name) const { return values_.find(name) != values_.end(); }
  const ParamValue& at(std::string_view name) const;
  void set(std::string name, ParamValue value) { values_[std::move(name)] = std::move(value); }
  const std::map<std::string, ParamValue, std::less<>>& values() const { return values_; }

 private:
  std::map<std::string, ParamValue, std::less<>> values_;
};

}  // namespace facet
