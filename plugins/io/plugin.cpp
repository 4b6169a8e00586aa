// The io plugin: stages that read recorded frames from disk and write results back.
#include "facet/plugin.hpp"

#include "io/cloud_sink.hpp"
#include "io/depth_sink.hpp"
#include "io/edges_sink.hpp"
#include "io/frames_source.hpp"
#include "io/labels_sink.hpp"
#include "io/objects_sink.hpp"
#include "io/overlay_sink.hpp"
#include "io/record_sink.hpp"

FACET_PLUGIN("facet_io", "0.1.0") {
  registrar.add<facet::io::FramesSource>();
  registrar.add<facet::io::LabelsSink>();
  registrar.add<facet::io::DepthSink>();
  registrar.add<facet::io::EdgesSink>();
  registrar.add<facet::io::ObjectsSink>();
  registrar.add<facet::io::OverlaySink>();
  registrar.add<facet::io::CloudSink>();
  registrar.add<facet::io::RecordSink>();
}
