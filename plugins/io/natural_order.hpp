#pragma once
// Natural ordering of file names: runs of digits compare by value, so learn2 < learn10.

#include <string_view>

namespace facet::io {

// Strict weak ordering. Digit runs compare numerically (leading zeros do not change the value;
// among equal values the shorter run sorts first), everything else compares by character.
bool natural_less(std::string_view a, std::string_view b);

}  // namespace facet::io
