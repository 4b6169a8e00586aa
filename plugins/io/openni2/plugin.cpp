// The openni2 plugin: live depth from OpenNI2 devices, .oni playback and recording, and what
// OpenNI2 sees in `facet doctor`.
#include "facet/plugin.hpp"

#include "openni2/oni_sink.hpp"
#include "openni2/openni_doctor.hpp"
#include "openni2/openni_source.hpp"

FACET_PLUGIN("facet_openni2", "0.1.0") {
  registrar.add<facet::openni2::OpenNi2Source>();
  registrar.add<facet::openni2::OniSink>();
  registrar.add_diagnostic("OpenNI2", [] { return facet::openni2::openni_doctor_report(); });
}
