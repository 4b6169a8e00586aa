#pragma once
// Which patches touch in the image, and along how many pixel contacts.

#include "facet/types/images.hpp"
#include "facet/types/patches.hpp"

namespace facet::algo {

// Two patches a != b (both non-zero) touch when a pixel of a has a pixel of b among its 8
// neighbours. contact_px counts the touching 8-neighbour pixel pairs, each unordered pair of
// pixels once (a straight border of length L gives about 3L contacts). Pairs (a, b) have a < b
// and are sorted. The result belongs to the frame of `patches` and has their count.
PatchAdjacency find_patch_contacts(const LabelImage& patches);

}  // namespace facet::algo
