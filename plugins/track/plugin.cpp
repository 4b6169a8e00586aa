// The track plugin: stages that carry segments from frame to frame.
#include "facet/plugin.hpp"

#include "track/track_labels.hpp"

FACET_PLUGIN("facet_track", "0.1.0") {
  registrar.add<facet::track::TrackLabels>();
}
