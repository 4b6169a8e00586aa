#include "grow/point_rows.hpp"

#include <algorithm>
#include <limits>

namespace facet::grow {
namespace {

__attribute__((target_clones("avx2", "default"))) void split_row(
    const float* __restrict points, const std::uint8_t* __restrict state, float* __restrict x,
    float* __restrict y, float* __restrict z, std::int32_t* __restrict wide_state, int width) {
  for (int i = 0; i < width; ++i) {
    x[i] = points[3 * i];
    y[i] = points[3 * i + 1];
    z[i] = points[3 * i + 2];
    wide_state[i] = state[i];
  }
}

}  // namespace

void PointRowRing::reset(int width, int height, int capacity, std::uint8_t guard_state) {
  width_ = width;
  height_ = height;
  capacity_ = capacity;
  guard_state_ = guard_state;
  stride_ = static_cast<std::size_t>(width) + 2 + 8;
  coordinates_.resize(static_cast<std::size_t>(capacity) * 3 * stride_);
  states_.resize(static_cast<std::size_t>(capacity) * stride_);
  // load() never writes the guard columns: set them once per frame.
  for (int slot = 0; slot < capacity; ++slot)
    fill_guard_row(slot - 1);
}

void PointRowRing::fill_guard_row(int row) {
  float* coordinates = coordinates_.data() + 3 * slot_offset(row);
  std::fill(coordinates, coordinates + 3 * stride_, std::numeric_limits<float>::quiet_NaN());
  std::int32_t* states = states_.data() + slot_offset(row);
  std::fill(states, states + stride_, guard_state_);
}

void PointRowRing::load(int row, const float* points, const std::uint8_t* state) {
  if (row < 0 || row >= height_) {
    fill_guard_row(row);
    return;
  }
  float* x = coordinates_.data() + 3 * slot_offset(row) + 1;
  split_row(points + 3 * static_cast<std::size_t>(row) * static_cast<std::size_t>(width_), state, x,
            x + stride_, x + 2 * stride_, states_.data() + slot_offset(row) + 1, width_);
}

}  // namespace facet::grow
