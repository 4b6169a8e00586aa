#pragma once
// template.counter: a source stage. It makes synthetic depth images, so that the template's
// graph runs without any dataset; a real source would read files or a camera instead.

#include <cstdint>
#include <facet/stage.hpp>

namespace facet_template {

class CounterSource final : public facet::Stage {
 public:
  static facet::StageSpec spec();
  explicit CounterSource(const facet::Params& params);

  void process(facet::ProcessContext& ctx) override;

 private:
  std::int64_t frames_;
  int width_;
  int height_;
  double near_mm_;
  double far_mm_;
  std::int64_t emitted_ = 0;  // state: this is why the stage is declared serial
};

}  // namespace facet_template
