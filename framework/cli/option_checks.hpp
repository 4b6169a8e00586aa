#pragma once
// Checks of numeric command-line options that say what is expected ("must be a non-negative
// integer, got '-1'"), where CLI11's own range checks print the range with DBL_MAX spelt out in
// hundreds of digits.

#include <CLI/CLI.hpp>

namespace facet::cli {

CLI::Validator non_negative_integer();  // 0, 1, 2, ...
CLI::Validator positive_integer();      // 1, 2, ...
CLI::Validator non_negative_number();   // 0, 0.5, 12, ... (finite)

}  // namespace facet::cli
