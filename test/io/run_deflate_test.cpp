// The run coder of label PNGs: what it writes inflates back exactly with a standard inflater,
// for runs of every length around deflate's limits and for data with no runs at all.
#include "io/run_deflate.hpp"

#include <gtest/gtest.h>
#include <libdeflate.h>

#include <cstdint>
#include <random>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes inflate(const Bytes& zlib, std::size_t size) {
  libdeflate_decompressor* decompressor = libdeflate_alloc_decompressor();
  Bytes out(size);
  std::size_t produced = 0;
  const libdeflate_result result = libdeflate_zlib_decompress(
      decompressor, zlib.data(), zlib.size(), out.data(), out.size(), &produced);
  libdeflate_free_decompressor(decompressor);
  EXPECT_EQ(result, LIBDEFLATE_SUCCESS);
  out.resize(produced);
  return out;
}

void expect_round_trip(const Bytes& data) {
  EXPECT_EQ(inflate(facet::io::png::zlib_compress_runs(data), data.size() + 16), data)
      << data.size() << " bytes";
}

TEST(RunDeflate, EmptyAndTinyInputs) {
  expect_round_trip({});
  expect_round_trip({7});
  expect_round_trip({7, 7});
  expect_round_trip({7, 7, 7});
  expect_round_trip({0, 1, 0, 1});
}

TEST(RunDeflate, RunsOfEveryLengthAroundTheMatchLimits) {
  for (std::size_t run = 1; run <= 2 * 258 + 6; ++run) {
    Bytes data(run + 3, 9);  // 1, 2, then the run, then 3
    data.front() = 1;
    data[1] = 2;
    data.back() = 3;
    expect_round_trip(data);
  }
}

TEST(RunDeflate, BytesWithoutRunsAndLongMixedStreams) {
  std::mt19937 rng(4);
  Bytes noise(5000);
  for (auto& byte : noise)
    byte = static_cast<std::uint8_t>(rng());
  expect_round_trip(noise);

  Bytes mixed;
  for (int block = 0; block < 2000; ++block) {
    const auto value = static_cast<std::uint8_t>(rng() % 3);
    for (auto n = rng() % 700; n > 0; --n)
      mixed.push_back(value);
    mixed.push_back(static_cast<std::uint8_t>(rng()));
  }
  expect_round_trip(mixed);
}

TEST(RunDeflate, RunsCompressWell) {
  const Bytes zeros(640 * 480 * 2, 0);
  EXPECT_LT(facet::io::png::zlib_compress_runs(zeros).size(), zeros.size() / 100);
}

}  // namespace
