#pragma once
// Batcher's odd-even merge sorting network for a fixed number of inputs, built at compile time.
//
// The median kernels run this network on SIMD vectors, one pixel per lane, so every comparator
// is a branch-free min/max pair. The compiler drops the min or max of comparators whose result
// never reaches the median, so the full network costs no more than a hand-pruned one.

#include <array>
#include <cstddef>

namespace facet::filters {

struct Comparator {
  std::size_t low;   // receives the smaller value
  std::size_t high;  // receives the larger value
};

namespace detail {

constexpr std::size_t next_power_of_two(std::size_t n) {
  std::size_t p = 1;
  while (p < n)
    p *= 2;
  return p;
}

// Visits the comparators of the network for the next power of two and keeps those whose wires
// both exist: the missing wires act as +infinity, which a comparator would leave in place.
template <class Visit>
constexpr void for_each_batcher_comparator(std::size_t n, Visit visit) {
  const std::size_t size = next_power_of_two(n);
  for (std::size_t p = 1; p < size; p *= 2) {
    for (std::size_t k = p; k >= 1; k /= 2) {
      for (std::size_t j = k % p; j + k < size; j += 2 * k) {
        for (std::size_t i = 0; i < k; ++i) {
          const std::size_t a = i + j;
          const std::size_t b = i + j + k;
          if (a / (2 * p) == b / (2 * p) && b < n) visit(Comparator{a, b});
        }
      }
    }
  }
}

constexpr std::size_t batcher_size(std::size_t n) {
  std::size_t count = 0;
  for_each_batcher_comparator(n, [&count](Comparator) { ++count; });
  return count;
}

}  // namespace detail

// The comparators that sort N values in ascending order, in the order they must be applied.
template <std::size_t N>
constexpr auto sorting_network() {
  std::array<Comparator, detail::batcher_size(N)> network{};
  std::size_t index = 0;
  detail::for_each_batcher_comparator(N, [&](Comparator c) { network[index++] = c; });
  return network;
}

}  // namespace facet::filters
