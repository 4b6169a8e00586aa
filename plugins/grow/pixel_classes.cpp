#include "grow/pixel_classes.hpp"

#include <cstdint>
#include <cstring>

namespace facet::grow {
namespace {

using Floats = float __attribute__((vector_size(32)));
using Ints = std::int32_t __attribute__((vector_size(32)));
using Bytes = std::int8_t __attribute__((vector_size(8)));

// One row, 8 pixels at a time: the z of 8 interleaved points are gathered from three vector
// loads with two shuffles, instead of a strided scalar load per pixel.
__attribute__((target_clones("avx2", "default"))) void classify_row(
    const unsigned char* __restrict edge, const float* __restrict xyz,
    unsigned char* __restrict out, int width) {
  int x = 0;
  for (; x + 8 <= width; x += 8) {
    Floats a;
    Floats b;
    Floats c;
    std::memcpy(&a, xyz + 3 * x, sizeof(a));
    std::memcpy(&b, xyz + 3 * x + 8, sizeof(b));
    std::memcpy(&c, xyz + 3 * x + 16, sizeof(c));
    // z of points 0..7 sit at floats 2, 5, 8, 11, 14, 17, 20 and 23 of the 24.
    const Floats ab = __builtin_shuffle(a, b, Ints{2, 5, 8, 11, 14, 0, 0, 0});
    const Floats z = __builtin_shuffle(ab, c, Ints{0, 1, 2, 3, 4, 9, 12, 15});
    // A NaN z compares false: invalid.
    const Bytes valid = __builtin_convertvector(z > Floats{}, Bytes);  // 0 or -1
    Bytes is_edge;
    std::memcpy(&is_edge, edge + x, sizeof(is_edge));
    const Bytes surface = is_edge == Bytes{};  // 0 or -1
    // kSurfacePixel = 2, kEdgePixel = 1, kInvalidPixel = 0.
    const Bytes classes = valid & (Bytes{} + 1 + (surface & 1));
    std::memcpy(out + x, &classes, sizeof(classes));
  }
  for (; x < width; ++x) {
    const bool valid = xyz[3 * x + 2] > 0.0F;
    out[x] = valid ? (edge[x] != 0 ? kEdgePixel : kSurfacePixel) : kInvalidPixel;
  }
}

}  // namespace

cv::Mat classify_pixels(const cv::Mat& edge_mask, const cv::Mat& points) {
  cv::Mat classes(edge_mask.size(), CV_8UC1);
  for (int row = 0; row < edge_mask.rows; ++row) {
    classify_row(edge_mask.ptr<unsigned char>(row), points.ptr<float>(row),
                 classes.ptr<unsigned char>(row), edge_mask.cols);
  }
  return classes;
}

}  // namespace facet::grow
