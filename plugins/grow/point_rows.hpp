#pragma once
// The rows the assignment wavefront is working on, split into planes (structure of arrays) so
// that 8 neighbouring pixels load as one vector per plane: x, y and z of the points (metres)
// and the state byte widened to 32 bits, in a ring. Each row is split once, while it is hot.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace facet::grow {

class PointRowRing {
 public:
  // Holds `capacity` rows of `width` pixels. Rows -1 and `height` (outside the image) and one
  // guard column on each side of every row read as NaN points with state `guard_state`.
  void reset(int width, int height, int capacity, std::uint8_t guard_state);
  // Splits row `row` (-1..height) of the CV_32FC3 data `points` and of the state row `state`
  // (at column 0; unused outside the image) into the ring, replacing the row that was
  // `capacity` rows earlier.
  void load(int row, const float* points, const std::uint8_t* state);
  // Planes of a loaded row at column 0; columns -1..width + 8 are readable.
  const float* coordinates(int row, int coordinate) const {
    return coordinates_.data() + 3 * slot_offset(row) +
           static_cast<std::size_t>(coordinate) * stride_ + 1;
  }
  std::int32_t* state(int row) { return states_.data() + slot_offset(row) + 1; }
  const std::int32_t* state(int row) const { return states_.data() + slot_offset(row) + 1; }

 private:
  std::size_t slot_offset(int row) const {
    return static_cast<std::size_t>((row + 1) % capacity_) * stride_;
  }
  void fill_guard_row(int row);

  int width_ = 0;
  int height_ = 0;
  int capacity_ = 1;
  std::int32_t guard_state_ = 0;
  std::size_t stride_ = 0;          // of a plane: width + guard columns + vector slack
  std::vector<float> coordinates_;  // per slot: the x, y and z planes
  std::vector<std::int32_t> states_;
};

}  // namespace facet::grow
