#pragma once
// Runs of equal labels along the raster. A label image is mostly long runs (a patch's row, the
// background between objects), so a pass that counts or maps labels once per run instead of once
// per pixel does a fraction of the work.

#include <cstddef>
#include <cstdint>

namespace facet::algo {

// The end of the run of label[begin]'s value that starts at `begin` (begin < total): the first
// index after it whose label differs, or `total`. Blocks of 16 labels are compared at once.
inline std::size_t label_run_end(const std::int32_t* label, std::size_t begin, std::size_t total) {
  const std::int32_t id = label[begin];
  constexpr std::size_t kBlock = 16;
  std::size_t end = begin + 1;
  while (end + kBlock <= total) {
    std::uint32_t differs = 0;
    for (std::size_t k = 0; k < kBlock; ++k)
      differs |= static_cast<std::uint32_t>(label[end + k] ^ id);
    if (differs != 0) break;
    end += kBlock;
  }
  while (end < total && label[end] == id)
    ++end;
  return end;
}

// Calls visit(id, begin, end) for each run [begin, end) of one label, in raster order.
template <typename Visit>
void for_each_label_run(const std::int32_t* label, std::size_t total, Visit&& visit) {
  for (std::size_t begin = 0; begin < total;) {
    const std::size_t end = label_run_end(label, begin, total);
    visit(label[begin], begin, end);
    begin = end;
  }
}

}  // namespace facet::algo
