#include "synthetic/hard_presets.hpp"

#include <algorithm>

#include "synthetic/household_objects.hpp"

namespace facet::synthetic {
namespace {

int object_count(const std::vector<Group>& groups) {
  int count = 0;
  for (const Group& group : groups)
    count += static_cast<int>(group.members.size());
  return count;
}

// Large groups first: rejection sampling finds room for them while the table is empty.
void largest_first(std::vector<Group>& groups) {
  std::stable_sort(groups.begin(), groups.end(),
                   [](const Group& a, const Group& b) { return a.radius > b.radius; });
}

// Books, magazines, trays and tins, each with one to three objects standing on it, and a few
// objects (any kind, cups, bowls) around them.
PresetDraw on_flat(RandomStream& random) {
  PresetDraw draw{{}, {-0.42, 0.42, -0.25, 0.38}, 0.03};
  const int flats = random.uniform_int(2, 3);
  for (int i = 0; i < flats; ++i)
    draw.groups.push_back(flat_with_items(flat_object(random), random.uniform_int(1, 3), random));
  const int others = random.uniform_int(2, 3);
  for (int i = 0; i < others; ++i) {
    switch (random.uniform_int(0, 2)) {
      case 0:
        draw.groups.push_back(single(random_object(random, 1.0)));
        break;
      case 1:
        draw.groups.push_back(single(random_cup(random)));
        break;
      default:
        draw.groups.push_back(single(random_bowl(random, 0.8)));
        break;
    }
  }
  largest_first(draw.groups);
  return draw;
}

// 15-25 objects packed close: touching pairs, stacks, a flat object carrying others, cups and
// bowls, and small objects of every kind filling the rest, 5 mm between bounding circles.
PresetDraw pile(RandomStream& random) {
  PresetDraw draw{{}, {-0.45, 0.45, -0.26, 0.4}, 0.005};
  const int target = random.uniform_int(15, 25);
  draw.groups.push_back(touching_boxes(random));
  draw.groups.push_back(box_and_round(random));
  draw.groups.push_back(stack(random, 2));
  draw.groups.push_back(stack(random, 3));
  draw.groups.push_back(flat_with_items(flat_object(random), random.uniform_int(1, 2), random));
  draw.groups.push_back(single(random_cup(random)));
  draw.groups.push_back(single(random_bowl(random, 0.8)));
  while (object_count(draw.groups) < target) {
    const bool pair_fits = object_count(draw.groups) + 2 <= target;
    switch (random.uniform_int(0, 5)) {
      case 0:
        draw.groups.push_back(single(random_cup(random)));
        break;
      case 1:
        draw.groups.push_back(single(random_bowl(random, 0.7)));
        break;
      case 2:
        draw.groups.push_back(pair_fits ? touching_boxes(random)
                                        : single(random_object(random, 0.7)));
        break;
      default:
        draw.groups.push_back(single(random_object(random, 0.7)));
        break;
    }
  }
  largest_first(draw.groups);
  return draw;
}

// A real office table: books and a magazine lying flat (small objects on the first book), a
// flat tin, cereal-like tall boxes, bowls, cups, a can lying on its side, and small boxes and
// other objects up to 10-16 objects in all.
PresetDraw office(RandomStream& random) {
  PresetDraw draw{{}, {-0.45, 0.45, -0.25, 0.4}, 0.015};
  const int target = random.uniform_int(10, 16);
  draw.groups.push_back(flat_with_items(book(random), random.uniform_int(1, 2), random));
  if (random.chance(0.5)) draw.groups.push_back(single(book(random)));
  draw.groups.push_back(single(magazine(random)));
  draw.groups.push_back(single(flat_tin(random)));
  const int cereals = random.uniform_int(1, 2);
  for (int i = 0; i < cereals; ++i)
    draw.groups.push_back(single(cereal_box(random)));
  const int bowls = random.uniform_int(1, 2);
  for (int i = 0; i < bowls; ++i)
    draw.groups.push_back(single(random_bowl(random, 1.0)));
  const int cups = random.uniform_int(1, 2);
  for (int i = 0; i < cups; ++i)
    draw.groups.push_back(single(random_cup(random)));
  draw.groups.push_back(single(lying_can(random)));
  while (object_count(draw.groups) < target) {
    if (random.chance(0.5)) {
      draw.groups.push_back(single(box(0, 0, 0, random_box_half(random, 0.7), random_yaw(random))));
    } else {
      draw.groups.push_back(single(random_object(random, 0.8)));
    }
  }
  largest_first(draw.groups);
  return draw;
}

// Bowls and cups, whose insides the camera sees through their open tops, and a few boxes.
PresetDraw containers(RandomStream& random) {
  PresetDraw draw{{}, {-0.4, 0.4, -0.24, 0.34}, 0.025};
  const int bowls = random.uniform_int(2, 3);
  for (int i = 0; i < bowls; ++i)
    draw.groups.push_back(single(random_bowl(random, 1.0)));
  const int cups = random.uniform_int(2, 4);
  for (int i = 0; i < cups; ++i)
    draw.groups.push_back(single(random_cup(random)));
  const int boxes = random.uniform_int(2, 3);
  for (int i = 0; i < boxes; ++i)
    draw.groups.push_back(single(box(0, 0, 0, random_box_half(random, 1.0), random_yaw(random))));
  largest_first(draw.groups);
  return draw;
}

}  // namespace

std::optional<ObjectCount> hard_preset_object_range(const std::string& preset) {
  // on_flat: 2-3 flat objects with 1-3 each, and 2-3 others; office: at least its 8 fixed
  // kinds, filled up to the 10-16 drawn.
  if (preset == "on_flat") return ObjectCount{6, 15};
  if (preset == "pile20") return ObjectCount{15, 25};
  if (preset == "office") return ObjectCount{10, 16};
  if (preset == "containers") return ObjectCount{6, 10};
  return std::nullopt;
}

std::optional<PresetDraw> draw_hard_preset(const std::string& preset, RandomStream& random) {
  if (preset == "on_flat") return on_flat(random);
  if (preset == "pile20") return pile(random);
  if (preset == "office") return office(random);
  if (preset == "containers") return containers(random);
  return std::nullopt;
}

}  // namespace facet::synthetic
