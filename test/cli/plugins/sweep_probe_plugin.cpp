// A test stage for `facet compare --sweep`: it passes its depth input through and reports its
// own parameters as metrics, so that a test can see which value each point of a sweep ran with,
// and an `f` of known shape over `gain` (flat at 0.9 on [0.3, 0.6], falling 1 per unit outside,
// 0.001 lower per `count`), so that a test knows the best point and the plateau in advance.

#include <algorithm>
#include <facet/plugin.hpp>
#include <facet/types/images.hpp>

namespace {

class SweepProbe final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("test.sweep_probe", "Reports its parameters as metrics.")
        .input<facet::DepthImage>("depth", "Any depth image.")
        .output<facet::DepthImage>("depth", "The input, unchanged.")
        .param("gain", 0.5, "Reported as the metric 'gain'.", {.min = 0.0, .max = 1.0})
        .param("count", 3, "Reported as the metric 'count'.", {.min = 0, .max = 20})
        .param("label", "probe", "A string parameter (cannot be swept).")
        .param("flag", false, "A boolean parameter (cannot be swept).");
  }
  explicit SweepProbe(const facet::Params& params)
      : gain_(params.get_double("gain")), count_(params.get_int("count")) {}

  void process(facet::ProcessContext& ctx) override {
    ctx.output_packet("depth", ctx.input_packet("depth"));
    ctx.metric("gain", gain_);
    ctx.metric("count", static_cast<double>(count_));
    const double outside = std::max({0.0, 0.3 - gain_, gain_ - 0.6});
    ctx.metric("f", 0.9 - outside - 0.001 * static_cast<double>(count_));
  }

 private:
  double gain_;
  std::int64_t count_;
};

}  // namespace

FACET_PLUGIN("sweep_probe", "1.0.0") {
  registrar.add<SweepProbe>();
}
