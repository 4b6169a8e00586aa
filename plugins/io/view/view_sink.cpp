#include "view/view_sink.hpp"

#include <opencv2/core.hpp>
#include <utility>

#include "facet/contract.hpp"
#include "facet/types/images.hpp"
#include "view/display_probe.hpp"
#include "view/view_render.hpp"

namespace facet::view {
namespace {

const OptionalIn<DepthImage> kDepth{"depth", "Depth, CV_16UC1 mm or CV_32FC1 m."};
const OptionalIn<NormalImage> kNormals{"normals", "Unit normals, CV_32FC3."};
const OptionalIn<EdgeImage> kEdges{"edges", "Edge score and mask."};
const OptionalIn<LabelImage> kLabels{"labels", "Segment ids, CV_32SC1 (0 = background)."};
const EnumParam<Show> kShow{"show",
                            Show::labels,
                            {{Show::depth, "depth"},
                             {Show::normals, "normals"},
                             {Show::edges, "edges"},
                             {Show::labels, "labels"},
                             {Show::all, "all"}},
                            "What to show: depth, normals, edges, labels (over depth when depth is "
                            "connected) or all connected inputs tiled."};
const Param<std::string> kTitle{"title", "facet",
                                "Window title (windows with the same title are the same window)."};
const Param<double> kScale{"scale", 1.0, "Zoom of the picture.", {.min = 0.1, .max = 8.0}};
const Param<int> kWaitMs{"wait_ms",
                         1,
                         "How long each frame waits for a key press in the window (also what lets "
                         "the window redraw); a larger value slows the graph down to a viewing "
                         "pace.",
                         {.unit = "ms", .min = 1, .max = 10000}};
const Param<bool> kRequireDisplay{"require_display", false,
                                  "Stop the run with an error when no window can be opened "
                                  "(default: warn once and run on without a window)."};

}  // namespace

StageSpec ViewSink::spec() {
  StageSpec spec("io.view",
                 "Shows depth, normals, edges or segments in a window while the graph runs "
                 "(see docs/cameras.md).\n"
                 "'show' picks the picture: depth in grey (near bright, no measurement "
                 "black), normals as colours (red (1 + x) / 2, green (1 + y) / 2, blue "
                 "(1 - z) / 2: surfaces facing the camera are blue), edges "
                 "(score in grey, edge pixels magenta, no surface black), labels in io.overlay's "
                 "colours over "
                 "the depth's grey, or all of the connected inputs tiled two per row. Every "
                 "input is optional. With no display (DISPLAY unset, or the X server not "
                 "answering) it warns once and does nothing more, so a headless robot runs "
                 "the same graph; require_display makes that an error instead. q or Esc in "
                 "the window closes it for the rest of the run (a sink cannot end the "
                 "stream: stop the run with Ctrl-C or --frames).");
  return spec
      .declare(kDepth, kNormals, kEdges, kLabels, kShow, kTitle, kScale, kWaitMs, kRequireDisplay)
      .concurrency(Concurrency::serial);
}

ViewSink::ViewSink(const Params& params)
    : show_(kShow(params)),
      title_(kTitle(params)),
      scale_(kScale(params)),
      wait_ms_(kWaitMs(params)),
      require_display_(kRequireDisplay(params)) {}

ViewSink::~ViewSink() {
  close();
}

void ViewSink::open(const OpenContext& /*ctx*/) {
  gave_up_ = false;
  no_display_reason_.clear();
  DisplayCheck check = check_display();
  if (!check.problem) {
    display_hold_ = std::move(check.connection);
    return;
  }
  if (require_display_) {
    throw StageError("cannot open window '" + title_ + "': " + *check.problem +
                     " (param require_display is true)");
  }
  no_display_reason_ = *check.problem;
}

void ViewSink::process(ProcessContext& ctx) {
  if (gave_up_) return;
  if (!no_display_reason_.empty()) {
    ctx.warn("io.view shows nothing: " + no_display_reason_ + "; the graph runs on without a " +
             "window");
    gave_up_ = true;
    return;
  }
  ViewInputs inputs;
  inputs.depth = kDepth(ctx);
  inputs.normals = kNormals(ctx);
  inputs.edges = kEdges(ctx);
  inputs.labels = kLabels(ctx);
  cv::Mat picture = render_view(inputs, show_, scale_);
  if (picture.empty()) return;  // this frame lacks what `show` needs (a skipped node)

  if (!window_) window_ = std::make_unique<WindowThread>(title_, wait_ms_);
  const WindowThread::Outcome outcome = window_->show(std::move(picture));
  if (!outcome.error.empty()) {
    if (require_display_) {
      throw StageError("cannot show window '" + title_ + "': " + outcome.error);
    }
    ctx.warn("io.view shows nothing: OpenCV cannot show window '" + title_ + "': " + outcome.error +
             "; the graph runs on without a window");
    gave_up_ = true;
  } else if (outcome.closed_by_user) {
    ctx.warn("window '" + title_ + "' closed (q/Esc): io.view shows nothing more; the graph " +
             "runs on until its source ends (Ctrl-C stops it)");
    gave_up_ = true;
  }
}

void ViewSink::close() {
  window_.reset();  // takes the window down
  display_hold_.reset();
}

}  // namespace facet::view
