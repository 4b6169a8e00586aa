#pragma once
// The colours io.overlay and io.cloud give segment ids: a fixed function of the id, so an id has
// the same colour in every frame, in every run and in both outputs.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "facet/contract.hpp"

namespace facet::io {

struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;

  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// The colour of segment `id` (id 0, the background, has no colour of its own: callers leave it
// uncoloured). Hue steps by the golden ratio of a turn from id to id, so consecutive ids are far
// apart on the colour wheel; saturation (2 levels, from 0.67) and brightness (3 levels) cycle
// with the id, so ids whose hues come close still differ. No id is a grey.
Rgb label_colour(std::uint32_t id);

// Parses "#rrggbb" (or "rrggbb"), hexadecimal, either case; nothing when it is not one.
std::optional<Rgb> parse_hex_colour(std::string_view text);

// "#rrggbb", lower case.
std::string hex_colour(const Rgb& colour);

}  // namespace facet::io

// A colour parameter (io.overlay's border_colour and edge_colour), written "#rrggbb".
template <>
struct facet::ParamTraits<facet::io::Rgb> {
  static std::variant<facet::io::Rgb, std::string> parse(std::string_view text);
  static std::string format(const facet::io::Rgb& colour) { return facet::io::hex_colour(colour); }
};
