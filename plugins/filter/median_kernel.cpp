#include "filter/median_kernel.hpp"

#include <cstddef>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

#include "filter/sorting_network.hpp"

// The kernels are compiled twice on x86-64, for AVX2 and for the baseline, and the loader picks
// one at start-up; everywhere else the compiler's default target is used.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define FACET_MEDIAN_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define FACET_MEDIAN_CLONES
#endif

// Every function that takes or returns a vector is inlined into the row kernels below, so no
// vector crosses a call boundary and GCC's note about the AVX calling convention does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace facet::filters {
namespace {

typedef std::int16_t I16Vec __attribute__((vector_size(kMedianVectorBytes)));
typedef float F32Vec __attribute__((vector_size(kMedianVectorBytes)));
typedef std::int32_t I32Vec __attribute__((vector_size(kMedianVectorBytes)));

template <class Scalar>
struct LaneTraits;

template <>
struct LaneTraits<std::int16_t> {
  using Vec = I16Vec;
  using Mask = I16Vec;
  using MaskScalar = std::int16_t;
  static constexpr std::int16_t low = std::numeric_limits<std::int16_t>::min();
  static constexpr std::int16_t high = std::numeric_limits<std::int16_t>::max();
};

template <>
struct LaneTraits<float> {
  using Vec = F32Vec;
  using Mask = I32Vec;
  using MaskScalar = std::int32_t;
  static constexpr float low = -std::numeric_limits<float>::infinity();
  static constexpr float high = std::numeric_limits<float>::infinity();
};

template <class Vec, class Scalar>
[[gnu::always_inline]] inline Vec splat(Scalar value) {
  Vec v;
  for (std::size_t i = 0; i < sizeof(Vec) / sizeof(Scalar); ++i)
    v[i] = value;
  return v;
}

template <class Vec, class Scalar>
[[gnu::always_inline]] inline Vec load(const Scalar* p) {
  Vec v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

template <class Vec, std::size_t N, std::size_t... I>
[[gnu::always_inline]] inline void apply_network(Vec* v, std::index_sequence<I...>) {
  static constexpr auto network = sorting_network<N>();
  (([&] {
     constexpr Comparator c = network[I];
     const Vec a = v[c.low];
     const Vec b = v[c.high];
     v[c.low] = a < b ? a : b;
     v[c.high] = a < b ? b : a;
   }()),
   ...);
}

template <class Scalar, int kSize, bool kFillHoles>
[[gnu::always_inline]] inline void median_row(const Scalar* const* rows, Scalar* out,
                                              int width_padded) {
  using Traits = LaneTraits<Scalar>;
  using Vec = typename Traits::Vec;
  using Mask = typename Traits::Mask;
  using MaskScalar = typename Traits::MaskScalar;
  constexpr std::size_t kCount = kSize * kSize;
  constexpr int kLanes = static_cast<int>(sizeof(Vec) / sizeof(Scalar));
  constexpr auto kNetworkSize = sorting_network<kCount>().size();
  // More than half of the window valid <=> at most this many invalid values.
  constexpr int kMaxInvalidToFill = static_cast<int>(kCount / 2);

  const Vec low = splat<Vec>(Traits::low);
  const Vec high = splat<Vec>(Traits::high);

  for (int x = 0; x < width_padded; x += kLanes) {
    Vec window[kCount];
#pragma GCC unroll 5
    for (int dy = 0; dy < kSize; ++dy) {
#pragma GCC unroll 5
      for (int dx = 0; dx < kSize; ++dx)
        window[dy * kSize + dx] = load<Vec>(rows[dy] + x + dx);
    }
    const Vec centre = window[kCount / 2];

    Mask odd_invalid_seen = {};  // all-ones in lanes that have seen an odd number of invalids
    Mask invalid_count = {};     // minus the number of invalid values (masks are -1)
#pragma GCC unroll 25
    for (std::size_t i = 0; i < kCount; ++i) {
      const Mask invalid = window[i] == low;
      window[i] = (invalid & odd_invalid_seen) ? high : window[i];
      odd_invalid_seen ^= invalid;
      if constexpr (kFillHoles) invalid_count += invalid;
    }

    apply_network<Vec, kCount>(window, std::make_index_sequence<kNetworkSize>{});

    Mask keep_median = centre != low;
    if constexpr (kFillHoles) {
      keep_median |= invalid_count >= splat<Mask>(static_cast<MaskScalar>(-kMaxInvalidToFill));
    }
    const Vec result = keep_median ? window[kCount / 2] : centre;
    std::memcpy(out + x, &result, sizeof result);
  }
}

template <class Scalar>
[[gnu::always_inline]] inline void dispatch_row(const Scalar* const* rows, Scalar* out,
                                                int width_padded, int size, bool fill_holes) {
  if (size == 3) {
    fill_holes ? median_row<Scalar, 3, true>(rows, out, width_padded)
               : median_row<Scalar, 3, false>(rows, out, width_padded);
  } else if (size == 5) {
    fill_holes ? median_row<Scalar, 5, true>(rows, out, width_padded)
               : median_row<Scalar, 5, false>(rows, out, width_padded);
  } else {
    throw std::invalid_argument("median window size must be 3 or 5");
  }
}

}  // namespace

FACET_MEDIAN_CLONES
void median_row_i16(const std::int16_t* const* rows, std::int16_t* out, int width_padded, int size,
                    bool fill_holes) {
  dispatch_row(rows, out, width_padded, size, fill_holes);
}

FACET_MEDIAN_CLONES
void median_row_f32(const float* const* rows, float* out, int width_padded, int size,
                    bool fill_holes) {
  dispatch_row(rows, out, width_padded, size, fill_holes);
}

}  // namespace facet::filters
