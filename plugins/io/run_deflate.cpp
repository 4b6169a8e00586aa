#include "io/run_deflate.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstddef>

namespace facet::io::png {
namespace {

// RFC 1951, section 3.2.5: match lengths 3..258 as a length symbol (257..285) plus extra bits.
constexpr std::array<int, 29> kLengthBase = {3,  4,  5,  6,   7,   8,   9,   10,  11, 13,
                                             15, 17, 19, 23,  27,  31,  35,  43,  51, 59,
                                             67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<int, 29> kLengthExtraBits = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                                  2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr int kMinMatch = 3;
constexpr int kMaxMatch = 258;
constexpr int kEndOfBlock = 256;

// Deflate writes bits least significant first, but Huffman codes most significant bit first:
// codes are stored here already reversed, ready to be put into the stream as numbers.
struct Code {
  std::uint32_t bits = 0;
  int length = 0;
};

constexpr std::uint32_t reversed(std::uint32_t code, int length) {
  std::uint32_t out = 0;
  for (int i = 0; i < length; ++i)
    out |= ((code >> i) & 1u) << (length - 1 - i);
  return out;
}

// The fixed literal/length code of RFC 1951, section 3.2.6.
constexpr std::array<Code, 288> fixed_literal_codes() {
  std::array<Code, 288> codes{};
  for (std::uint32_t symbol = 0; symbol < 288; ++symbol) {
    if (symbol < 144)
      codes[symbol] = {reversed(0x30 + symbol, 8), 8};
    else if (symbol < 256)
      codes[symbol] = {reversed(0x190 + symbol - 144, 9), 9};
    else if (symbol < 280)
      codes[symbol] = {reversed(symbol - 256, 7), 7};
    else
      codes[symbol] = {reversed(0xc0 + symbol - 280, 8), 8};
  }
  return codes;
}

// Every match length as one bit pattern: its length symbol's code followed by the extra bits,
// then the distance code for distance 1 (fixed 5-bit code 0, no extra bits).
constexpr std::array<Code, kMaxMatch + 1> match_codes(const std::array<Code, 288>& literals) {
  std::array<Code, kMaxMatch + 1> codes{};
  for (int length = kMinMatch; length <= kMaxMatch; ++length) {
    std::size_t index = kLengthBase.size() - 1;
    while (kLengthBase[index] > length)
      --index;
    const Code& symbol = literals[257 + index];
    const auto extra = static_cast<std::uint32_t>(length - kLengthBase[index]);
    const int extra_bits = kLengthExtraBits[index];
    codes[static_cast<std::size_t>(length)] = {symbol.bits | (extra << symbol.length),
                                               symbol.length + extra_bits + 5};
  }
  return codes;
}

class BitWriter {
 public:
  explicit BitWriter(std::vector<std::uint8_t>& out) : out_(out) {}

  void put(std::uint32_t bits, int length) {
    buffer_ |= std::uint64_t{bits} << count_;
    count_ += length;
    while (count_ >= 8) {
      out_.push_back(static_cast<std::uint8_t>(buffer_));
      buffer_ >>= 8;
      count_ -= 8;
    }
  }
  void flush() {
    if (count_ > 0) out_.push_back(static_cast<std::uint8_t>(buffer_));
    buffer_ = 0;
    count_ = 0;
  }

 private:
  std::vector<std::uint8_t>& out_;
  std::uint64_t buffer_ = 0;
  int count_ = 0;
};

}  // namespace

std::vector<std::uint8_t> zlib_compress_runs(std::span<const std::uint8_t> data) {
  static constexpr std::array<Code, 288> literals = fixed_literal_codes();
  static constexpr std::array<Code, kMaxMatch + 1> matches = match_codes(literals);

  std::vector<std::uint8_t> out;
  out.reserve(64 + data.size() / 16);
  out.push_back(0x78);  // CMF: deflate, 32 KiB window
  out.push_back(0x01);  // FLG: fastest compression; (0x78 << 8 | 0x01) % 31 == 0
  BitWriter bits(out);
  bits.put(1, 1);  // BFINAL: the only block
  bits.put(1, 2);  // BTYPE 01: fixed Huffman codes

  const std::size_t size = data.size();
  std::size_t at = 0;
  while (at < size) {
    // A run continues the byte before it: code as many repeats as there are, in matches of at
    // most 258; a tail of one or two repeats goes out as literals.
    if (at > 0 && data[at] == data[at - 1]) {
      std::size_t run = 1;
      while (at + run < size && data[at + run] == data[at - 1])
        ++run;
      while (run >= kMinMatch) {
        const int length = static_cast<int>(std::min<std::size_t>(run, kMaxMatch));
        const Code& code = matches[static_cast<std::size_t>(length)];
        bits.put(code.bits, code.length);
        run -= static_cast<std::size_t>(length);
        at += static_cast<std::size_t>(length);
      }
      for (; run > 0; --run, ++at)
        bits.put(literals[data[at]].bits, literals[data[at]].length);
      continue;
    }
    bits.put(literals[data[at]].bits, literals[data[at]].length);
    ++at;
  }
  bits.put(literals[kEndOfBlock].bits, literals[kEndOfBlock].length);
  bits.flush();

  const std::uint32_t adler = libdeflate_adler32(1, data.data(), data.size());
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<std::uint8_t>(adler >> shift));
  return out;
}

}  // namespace facet::io::png
