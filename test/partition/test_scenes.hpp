#pragma once
// The scenes both partition stages are tested on (table coordinates in metres, see Tabletop).

#include "partition_scene.hpp"

namespace facet::test {

// Two boxes of equal height touching side by side, the right one set back: one blob.
inline PartitionInput two_boxes_side_by_side() {
  Tabletop t;
  t.box(-0.06, -0.04, {0.06, 0.05, 0.05}).box(0.06, 0.04, {0.06, 0.05, 0.05});
  return one_blob(t.builder().render());
}

// A small box centred on a larger one.
inline PartitionInput box_on_box() {
  Tabletop t;
  t.box(0.0, 0.0, {0.10, 0.08, 0.04}).box(0.0, 0.0, {0.05, 0.04, 0.04}, 20.0, 0.08);
  return one_blob(t.builder().render());
}

inline PartitionInput cylinder_on_box() {
  Tabletop t;
  t.box(0.0, 0.0, {0.10, 0.08, 0.04}).cylinder(0.0, 0.0, 0.04, 0.06, 0.08);
  return one_blob(t.builder().render());
}

// One box turned so that its top and two sides are visible.
inline PartitionInput single_box() {
  Tabletop t;
  t.box(0.0, 0.0, {0.08, 0.06, 0.05}, 30.0);
  return one_blob(t.builder().render());
}

inline PartitionInput single_cylinder() {
  Tabletop t;
  t.cylinder(0.0, 0.0, 0.05, 0.08);
  return one_blob(t.builder().render());
}

// Paper Fig. 9 right: the largest face (the top of a wide flat box) comes first, and its plane
// cuts through a tall box standing beside it.
inline PartitionInput tall_box_beside_flat_box() {
  Tabletop t;
  t.box(0.0, 0.0, {0.15, 0.12, 0.04}).box(0.19, 0.0, {0.04, 0.04, 0.10});
  return one_blob(t.builder().render());
}

}  // namespace facet::test
