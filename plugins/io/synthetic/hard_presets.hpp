#pragma once
// The hard-case presets, the scenes on which the segmentation pipeline fails on real tables:
// flat objects with others standing on them (on_flat), dense piles (pile20), a mixed office
// table (office) and open containers (containers). Each draws its number of objects per layout.

#include <optional>
#include <string>
#include <vector>

#include "synthetic/layout_parts.hpp"
#include "synthetic/scene_layout.hpp"

namespace facet::synthetic {

struct PresetDraw {
  std::vector<Group> groups;  // largest first, so that they find room on the table
  Area area;                  // where they go on the table
  double gap = 0.0;           // least distance between the groups' bounding circles
};

// The fewest and most objects of a hard-case preset; nullopt for any other name.
std::optional<ObjectCount> hard_preset_object_range(const std::string& preset);

// One draw of a hard-case preset's groups; nullopt for any other name.
std::optional<PresetDraw> draw_hard_preset(const std::string& preset, RandomStream& random);

}  // namespace facet::synthetic
