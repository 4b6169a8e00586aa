#include "io/natural_order.hpp"

#include <cstddef>

namespace facet::io {
namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

std::size_t digit_run_end(std::string_view s, std::size_t begin) {
  while (begin < s.size() && is_digit(s[begin]))
    ++begin;
  return begin;
}

std::string_view strip_leading_zeros(std::string_view digits) {
  while (digits.size() > 1 && digits.front() == '0')
    digits.remove_prefix(1);
  return digits;
}

// <0, 0, >0 like strcmp, comparing two digit runs by value (of any length, no overflow).
int compare_numbers(std::string_view a, std::string_view b) {
  const std::string_view va = strip_leading_zeros(a);
  const std::string_view vb = strip_leading_zeros(b);
  if (va.size() != vb.size()) return va.size() < vb.size() ? -1 : 1;
  if (const int c = va.compare(vb); c != 0) return c;
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  return 0;
}

}  // namespace

bool natural_less(std::string_view a, std::string_view b) {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    if (is_digit(a[i]) && is_digit(b[j])) {
      const std::size_t end_a = digit_run_end(a, i);
      const std::size_t end_b = digit_run_end(b, j);
      if (const int c = compare_numbers(a.substr(i, end_a - i), b.substr(j, end_b - j)); c != 0) {
        return c < 0;
      }
      i = end_a;
      j = end_b;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return (a.size() - i) < (b.size() - j);
}

}  // namespace facet::io
