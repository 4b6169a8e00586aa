#pragma once
// A seeded random stream whose numbers are the same on every platform and standard library:
// xoshiro256** seeded through splitmix64, with the uniform and normal variates computed here
// (std::uniform_real_distribution and std::normal_distribution are implementation-defined).

#include <array>
#include <cstdint>

namespace facet::synthetic {

// Mixes several 64-bit words into one seed (splitmix64 finaliser), so that the streams of
// (seed, frame, purpose) are independent of each other.
std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b, std::uint64_t c = 0);

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed);

  std::uint64_t next_u64();
  // Uniform in [0, 1), 53 random bits.
  double uniform();
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Uniform integer in [low, high], both inclusive.
  int uniform_int(int low, int high);
  // Standard normal (Box-Muller; the second variate of each pair is kept for the next call).
  double normal();
  bool chance(double probability) { return uniform() < probability; }

 private:
  std::array<std::uint64_t, 4> state_{};
  double spare_normal_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace facet::synthetic
