#pragma once
// The ports every partition.* stage shares, so that the three stay interchangeable in a graph
// (a variant swaps one for another) and are documented alike. Each stage adds its adjacency input
// (required or optional) and any outputs of its own.

#include "facet/contract.hpp"
#include "facet/types/images.hpp"

namespace facet::partition {

inline const In<LabelImage> kBlobs{"blobs", "Object candidates, CV_32SC1 ids > 0; 0 = background."};
inline const In<LabelImage> kPatches{"patches", "Surface patch ids, CV_32SC1; 0 = in no patch."};
inline const In<PointImage> kPoints{"points",
                                    "3D points, CV_32FC3 in metres, NaN = invalid; same size."};
inline const Out<LabelImage> kObjects{"objects", "Object ids 1..count, CV_32SC1; 0 = background."};

}  // namespace facet::partition
