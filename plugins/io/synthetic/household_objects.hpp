#pragma once
// The objects of the hard-case presets: flat things lying on the table (books, magazines,
// trays, flat tins), open containers (cups, bowls), tall cereal-like boxes, and flat objects
// with a few objects standing on them. Each maker places its object resting on the table at the
// origin; sizes are drawn from the random stream.

#include "synthetic/layout_parts.hpp"

namespace facet::synthetic {

// A book: 14-30 cm long, 10-22 cm wide, 1.5-4 cm thick.
Solid book(RandomStream& random);
// A magazine: 20-30 cm by 15-21 cm, about 1 cm thick.
Solid magazine(RandomStream& random);
// A tray: 24-30 cm by 16-24 cm, 2-3 cm thick (a flat box: its rim is not modelled).
Solid tray(RandomStream& random);
// A flat round tin: 10-20 cm across, 1-4 cm high (an upright cylinder).
Solid flat_tin(RandomStream& random);
// One of the four above, at random.
Solid flat_object(RandomStream& random);

// A cup: 7-9 cm across, 8-11 cm high, walls 3-5 mm.
Solid random_cup(RandomStream& random);
// A bowl: rim `scale` * 11-20 cm across, 3-8 cm deep (0.5-0.8 of its sphere radius), walls 4-6 mm.
Solid random_bowl(RandomStream& random, double scale);
// A tall box like a cereal packet: 16-20 cm wide, 5-8 cm deep, 24-32 cm high.
Solid cereal_box(RandomStream& random);
// A cylinder lying on its side: 5-8 cm across, 12-20 cm long.
Solid lying_can(RandomStream& random);

// Whether `item`, resting on the top face of `base` (a box or an upright cylinder), has all of
// its contact with that top (its foot, its bottom face, its lowest point) inside the top.
bool rests_inside(const Solid& base, const Solid& item);

// A flat object with `items` objects (small boxes, cups, upright cylinders, spheres, small
// bowls) standing on its top, apart from each other; an item that finds no room is left out,
// but the first one always stands.
Group flat_with_items(const Solid& flat, int items, RandomStream& random);

}  // namespace facet::synthetic
