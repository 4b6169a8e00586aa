#pragma once
// io.view: shows depth, normals, edges or segments in a window while a graph runs. With no
// display it says so once and lets the graph run on (or stops it, with require_display).

#include <memory>
#include <string>

#include "facet/stage.hpp"
#include "view/view_render.hpp"
#include "view/window_thread.hpp"

namespace facet::view {

class ViewSink final : public Stage {
 public:
  static StageSpec spec();
  explicit ViewSink(const Params& params);
  ~ViewSink() override;

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;
  void close() override;

 private:
  // Parameters.
  Show show_;
  std::string title_;
  double scale_;
  int wait_ms_;
  bool require_display_;

  bool gave_up_ = false;  // no display, or closed by the user: pass frames through silently
  std::string no_display_reason_;
  std::shared_ptr<void> display_hold_;    // the display check's X connection, held while showing
  std::unique_ptr<WindowThread> window_;  // from the first picture on
};

}  // namespace facet::view
