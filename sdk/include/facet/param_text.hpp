#pragma once
// Building blocks for the ParamTraits of structured parameters (facet/contract.hpp) that are
// written as a fixed number of comma-separated numbers, e.g. a vector "0,-1,0" or a box
// "xmin,xmax,ymin,ymax,zmin,zmax".

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace facet {

// A parsed list: each field's number and its text without the spaces around it (for messages).
struct NumberList {
  std::vector<float> values;
  std::vector<std::string_view> fields;  // views into the parsed text
};

// Exactly `count` finite numbers separated by commas, spaces around each allowed. Otherwise the
// reason, e.g. "3 comma-separated numbers are needed, not 2" or "'a' is not a finite number".
std::variant<NumberList, std::string> parse_number_list(std::string_view text, std::size_t count);

// The numbers, comma-separated, each in the shortest form that reads back as the same float.
std::string format_number_list(std::span<const float> values);

}  // namespace facet
