#pragma once
// A zlib stream (RFC 1950 around RFC 1951 deflate) that codes only runs of a repeated byte, as
// matches at distance 1 with deflate's fixed Huffman codes, and every other byte as a literal.
//
// It is for label and mask images. Their rows are long runs of one id, which PNG's Sub filter
// turns into runs of zero bytes: a general deflater spends most of its time looking for matches
// that are all the same one here (libdeflate: about 1 ns per byte of a 640x480 label image; this
// coder: a fraction of that, at a similar size; bench/png_bench.cpp). On data without runs it
// stores bytes at 8-9 bits each, so it is not for photographs or depth.

#include <cstdint>
#include <span>
#include <vector>

namespace facet::io::png {

std::vector<std::uint8_t> zlib_compress_runs(std::span<const std::uint8_t> data);

}  // namespace facet::io::png
