#pragma once
// One output row of the valid-pixel median, on SIMD vectors (GCC vector extensions), one pixel
// per lane. Internal to ValidMedian; declared here so the kernel can be tested on its own.
//
// Input encoding: every invalid pixel (and the border around the image) holds the lowest value
// of the lane type. Invalid values are then replaced, alternately, by the lowest and the highest
// value — ceil(k/2) low ones and floor(k/2) high ones for k invalid values — so the plain median
// of the whole window equals the (lower) median of its valid values. That keeps the work a fixed
// sorting network with no per-pixel branch, which is what makes it fast.

#include <cstdint>

namespace facet::filters {

// Pixels per call step: the kernels read and write whole vectors of this many bytes.
inline constexpr int kMedianVectorBytes = 32;

// rows[i] points at the top-left window pixel of output x = 0 in window row i (size rows);
// every row must be readable for width_padded + size - 1 values, where width_padded is the output
// width rounded up to a whole number of vectors. Writes width_padded values to `out`.
// An output whose window centre is invalid is the (invalid) centre value, unless fill_holes is
// set and more than half of the window is valid.
void median_row_i16(const std::int16_t* const* rows, std::int16_t* out, int width_padded, int size,
                    bool fill_holes);
void median_row_f32(const float* const* rows, float* out, int width_padded, int size,
                    bool fill_holes);

// Values per vector, i.e. the multiple that width_padded must be.
inline constexpr int kMedianLanesI16 = kMedianVectorBytes / 2;
inline constexpr int kMedianLanesF32 = kMedianVectorBytes / 4;

}  // namespace facet::filters
