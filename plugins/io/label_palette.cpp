#include "io/label_palette.hpp"

#include <array>

namespace facet::io {
namespace {

// 2^32 / golden ratio: multiplying by it walks the 32-bit circle in golden-ratio steps.
constexpr std::uint32_t kGoldenStep = 0x9E3779B9U;

// HSV to RGB in integers: hue in 1/65536 turns, saturation and value in 0..255.
Rgb hsv_to_rgb(std::uint32_t hue_u16, std::uint32_t saturation, std::uint32_t value) {
  const std::uint32_t scaled = hue_u16 * 6U;  // < 6 * 65536
  const std::uint32_t sector = scaled >> 16;  // 0..5
  const std::uint32_t fraction = scaled & 0xFFFFU;
  const auto channel = [&](std::uint32_t amount) {  // value * (1 - saturation * amount / 65536)
    return static_cast<std::uint8_t>(value - (value * saturation / 255U) * amount / 65536U);
  };
  const std::uint8_t v = static_cast<std::uint8_t>(value);
  const std::uint8_t p = channel(65536U);
  const std::uint8_t q = channel(fraction);
  const std::uint8_t t = channel(65536U - fraction);
  switch (sector) {
    case 0:
      return {v, t, p};
    case 1:
      return {q, v, p};
    case 2:
      return {p, v, t};
    case 3:
      return {p, q, v};
    case 4:
      return {t, p, v};
    default:
      return {v, p, q};
  }
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

Rgb label_colour(std::uint32_t id) {
  // Chosen for the largest smallest CIE76 colour difference among ids 1..20 (about 20; among ids
  // 1..12 about 26). Ids whose hues come close differ by 8, 13, 21, 34, 55 or 89, which the
  // period of 2 and of 3 separate in saturation or brightness; ids 144 apart look alike.
  static constexpr std::array<std::uint32_t, 2> kSaturation = {225, 170};
  static constexpr std::array<std::uint32_t, 3> kValue = {255, 200, 150};
  const std::uint32_t hue = (id * kGoldenStep) >> 16;
  return hsv_to_rgb(hue, kSaturation[id % 2U], kValue[id % 3U]);
}

std::optional<Rgb> parse_hex_colour(std::string_view text) {
  if (!text.empty() && text.front() == '#') text.remove_prefix(1);
  if (text.size() != 6) return std::nullopt;
  std::array<std::uint8_t, 3> channels{};
  for (std::size_t i = 0; i < 3; ++i) {
    const int high = hex_digit(text[2 * i]);
    const int low = hex_digit(text[2 * i + 1]);
    if (high < 0 || low < 0) return std::nullopt;
    channels[i] = static_cast<std::uint8_t>(high * 16 + low);
  }
  return Rgb{channels[0], channels[1], channels[2]};
}

std::string hex_colour(const Rgb& colour) {
  constexpr char kDigits[] = "0123456789abcdef";
  std::string text = "#";
  for (const std::uint8_t channel : {colour.r, colour.g, colour.b}) {
    text += kDigits[channel / 16];
    text += kDigits[channel % 16];
  }
  return text;
}

}  // namespace facet::io

std::variant<facet::io::Rgb, std::string> facet::ParamTraits<facet::io::Rgb>::parse(
    std::string_view text) {
  if (const auto colour = io::parse_hex_colour(text)) return *colour;
  std::string why = "'";
  why.append(text);
  why.append("' is not a colour; write it as #rrggbb, e.g. #ff00ff");
  return why;
}
