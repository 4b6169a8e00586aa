#pragma once
// Row kernels of the assignment pass over its one-byte state plane, written so that the
// compiler vectorises them: they look at every pixel of a row, the rest of the pass only at the
// few pixels they mark.

#include <cstdint>

namespace facet::grow {

// State bytes: the round in which a pixel got its label (0 = a patch from region growing,
// rounds are 1..250), or one of these markers.
constexpr std::uint8_t kUnassignedState = 255;
constexpr std::uint8_t kInvalidState = 254;

// state[x] = 0 where labels[x] != 0, else kUnassignedState for a valid pixel (classes[x] !=
// kInvalidPixel) and kInvalidState otherwise. Returns how many pixels are kUnassignedState.
int fill_state_row(const std::int32_t* labels, const std::uint8_t* classes, std::uint8_t* state,
                   int width);

// candidate[x] = 1 where mid[x] is kUnassignedState and one of its 8 neighbours in the rows
// up, mid and down has the state `newest` (labelled in the previous round), else 0. The rows
// are read at x = -1 and x = width.
void find_round_candidates(const std::uint8_t* up, const std::uint8_t* mid,
                           const std::uint8_t* down, std::uint8_t newest, std::uint8_t* candidate,
                           int width);

// The rows around the row of a round: up, mid and down (index 0, 1, 2), each at column 0 with
// columns -1..width + 8 readable; outside the image the state is kInvalidState.
struct NeighbourRows {
  const float* coordinates[3][3];  // [row][x, y, z] planes of the points, metres
  const std::int32_t* state[3];    // the state bytes, widened
  const std::int32_t* labels[3];   // the label image (any value where the state is invalid)
};

// One round on the row `mid`: every candidate pixel (`candidate` bytes 0/1, readable up to a
// multiple of 8, 0 past `width`) takes the label of the neighbour that is 3D-closest among those
// labelled before `round` (state below it) and closer than the gate; the first of equals in
// kNeighbourSteps order wins, NaN never. A pixel that takes a label gets `round` in `state_row`
// (bytes) and in the widened state of `rows.state[1]`; `label_row` is `rows.labels[1]`.
// Vectorised across the 8 pixels of a word: each lane runs the sequential strict-< scan of its
// own 8 neighbours, so the choice is exactly that of the scan. A pixel labelled in this round
// has state `round`, so no other pixel of the round takes its label. Returns the number of
// pixels labelled.
int assign_nearest_neighbours(const NeighbourRows& rows, const std::uint8_t* candidate,
                              std::uint8_t round, float gate_sq_m2, std::int32_t* label_row,
                              std::uint8_t* state_row, std::int32_t* wide_state_row, int width);

}  // namespace facet::grow
