// A well-formed plugin with one stage and two `facet doctor` sections (one of which fails, as a
// driver stack that cannot be queried would); FACET_TEST_STAGE_NAME lets a second build of this
// file claim the same stage name, to test conflicts between plugins.

#include <facet/plugin.hpp>
#include <facet/types/images.hpp>
#include <stdexcept>
#include <string>

namespace {

class ConstantDepth final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec(FACET_TEST_STAGE_NAME, "Emits one constant depth image per frame.")
        .output<facet::DepthImage>("depth", "Every pixel at `value` millimetres.")
        .param("value", 500, "Depth of every pixel.", {.unit = "mm", .min = 0, .max = 65535});
  }
  explicit ConstantDepth(const facet::Params& params)
      : value_(static_cast<double>(params.get_int("value"))) {}

  void process(facet::ProcessContext& ctx) override {
    facet::DepthImage image;
    image.depth = cv::Mat(2, 3, CV_16UC1, cv::Scalar(value_));
    ctx.output("depth", std::move(image));
  }

 private:
  double value_;
};

}  // namespace

FACET_PLUGIN(FACET_TEST_PLUGIN_NAME, "1.2.3") {
  registrar.add<ConstantDepth>();
  registrar.add_diagnostic("Test sensor", [] {
    return std::string("driver: constant 1.0\ndevices: test://0 (Constant, facet)");
  });
  registrar.add_diagnostic("Test bus",
                           []() -> std::string { throw std::runtime_error("bus not powered"); });
}
