#include "facet/contract.hpp"

namespace facet::contract_detail {

std::optional<std::string> check_fits_int(const ParamValue& value) {
  const auto* integer = std::get_if<std::int64_t>(&value);
  if (integer == nullptr) return std::nullopt;  // the type check reports it
  if (*integer < std::numeric_limits<int>::min() || *integer > std::numeric_limits<int>::max()) {
    return "value " + std::to_string(*integer) + " does not fit a 32-bit integer";
  }
  return std::nullopt;
}

}  // namespace facet::contract_detail
