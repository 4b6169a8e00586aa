// The view plugin: a live window on a running graph (OpenCV highgui).
#include "facet/plugin.hpp"

#include "view/view_sink.hpp"

FACET_PLUGIN("facet_view", "0.1.0") {
  registrar.add<facet::view::ViewSink>();
}
