#include "facet/param.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace facet {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// Spelled out for compilers without class template argument deduction for aggregates (clang 14,
// which builds the fuzz targets).
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

std::optional<double> numeric(const ParamValue& value) {
  if (const auto* i = std::get_if<std::int64_t>(&value)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&value)) return *d;
  return std::nullopt;
}

bool same_value(const ParamValue& a, const ParamValue& b) {
  const auto na = numeric(a);
  const auto nb = numeric(b);
  if (na && nb) return *na == *nb;
  return a == b;
}

[[noreturn]] void throw_missing(std::string_view name, std::string_view wanted) {
  throw std::out_of_range("parameter '" + std::string(name) + "' is not a declared " +
                          std::string(wanted) + " parameter");
}

}  // namespace

std::string_view to_string(ParamType type) noexcept {
  switch (type) {
    case ParamType::boolean:
      return "bool";
    case ParamType::integer:
      return "int";
    case ParamType::real:
      return "real";
    case ParamType::string:
      return "string";
  }
  return "?";
}

std::string format_param_value(const ParamValue& value) {
  return std::visit(Overloaded{[](bool b) { return std::string(b ? "true" : "false"); },
                               [](std::int64_t i) { return std::to_string(i); },
                               [](double d) {
                                 std::ostringstream out;
                                 out.precision(15);
                                 out << d;
                                 std::string text = out.str();
                                 if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
                                 return text;
                               },
                               [](const std::string& s) { return s; }},
                    value);
}

std::optional<std::string> check_param_value(const ParamSpec& spec, const ParamValue& value) {
  const bool type_ok = [&] {
    switch (spec.type) {
      case ParamType::boolean:
        return std::holds_alternative<bool>(value);
      case ParamType::integer:
        return std::holds_alternative<std::int64_t>(value);
      case ParamType::real:
        return numeric(value).has_value();
      case ParamType::string:
        return std::holds_alternative<std::string>(value);
    }
    return false;
  }();
  if (!type_ok) {
    return "expected a value of type " + std::string(to_string(spec.type)) + ", got '" +
           format_param_value(value) + "'";
  }
  if (const auto n = numeric(value)) {
    if (std::isnan(*n)) return std::string("value is not a number");
    const auto& o = spec.options;
    if ((o.min && *n < *o.min) || (o.max && *n > *o.max)) {
      std::ostringstream msg;
      msg << "value " << format_param_value(value) << " is out of range [";
      msg << (o.min ? format_param_value(spec.type == ParamType::integer
                                             ? ParamValue(static_cast<std::int64_t>(*o.min))
                                             : ParamValue(*o.min))
                    : std::string("-inf"));
      msg << ", ";
      msg << (o.max ? format_param_value(spec.type == ParamType::integer
                                             ? ParamValue(static_cast<std::int64_t>(*o.max))
                                             : ParamValue(*o.max))
                    : std::string("inf"));
      msg << "]";
      return msg.str();
    }
  }
  if (!spec.options.choices.empty()) {
    for (const auto& choice : spec.options.choices) {
      if (same_value(choice, value)) return std::nullopt;
    }
    std::string msg = "value '" + format_param_value(value) + "' is not one of ";
    for (std::size_t i = 0; i < spec.options.choices.size(); ++i) {
      msg += (i ? ", " : "") + format_param_value(spec.options.choices[i]);
    }
    return msg;
  }
  if (spec.check) return spec.check(value);
  return std::nullopt;
}

std::variant<ParamValue, std::string> parse_param_value(const ParamSpec& spec,
                                                        std::string_view text) {
  const auto fail = [&](std::string_view what) {
    return std::variant<ParamValue, std::string>(
        std::in_place_index<1>,
        "expected " + std::string(what) + ", got '" + std::string(text) + "'");
  };
  switch (spec.type) {
    case ParamType::boolean:
      if (text == "true" || text == "on" || text == "yes") return ParamValue(true);
      if (text == "false" || text == "off" || text == "no") return ParamValue(false);
      return fail("a boolean (true or false)");
    case ParamType::integer: {
      std::int64_t v = 0;
      const auto* end = text.data() + text.size();
      const auto [ptr, ec] = std::from_chars(text.data(), end, v);
      if (ec != std::errc() || ptr != end || text.empty()) return fail("an integer");
      return ParamValue(v);
    }
    case ParamType::real: {
      // from_chars for double is in GCC 11+, but strtod handles "1e-3" and "inf" alike.
      const std::string copy(text);
      char* end = nullptr;
      const double v = std::strtod(copy.c_str(), &end);
      if (copy.empty() || end != copy.c_str() + copy.size() || std::isnan(v)) {
        return fail("a number");
      }
      return ParamValue(v);
    }
    case ParamType::string:
      return ParamValue(std::string(text));
  }
  return fail("a value");
}

const ParamValue& Params::at(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) {
    throw std::out_of_range("parameter '" + std::string(name) + "' is not declared");
  }
  return it->second;
}

bool Params::get_bool(std::string_view name) const {
  const auto* v = std::get_if<bool>(&at(name));
  if (v == nullptr) throw_missing(name, "bool");
  return *v;
}

std::int64_t Params::get_int(std::string_view name) const {
  const auto* v = std::get_if<std::int64_t>(&at(name));
  if (v == nullptr) throw_missing(name, "int");
  return *v;
}

double Params::get_double(std::string_view name) const {
  const auto v = numeric(at(name));
  if (!v) throw_missing(name, "real");
  return *v;
}

const std::string& Params::get_string(std::string_view name) const {
  const auto* v = std::get_if<std::string>(&at(name));
  if (v == nullptr) throw_missing(name, "string");
  return *v;
}

}  // namespace facet
