#include "facet/testing/stage_runner.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "facet/types/images.hpp"

namespace {

// Adds `offset_mm` to every valid depth pixel; counts its lifecycle calls.
class AddOffset final : public facet::Stage {
 public:
  static facet::StageSpec spec() {
    return facet::StageSpec("test.add_offset", "Adds a constant to valid depth.")
        .input<facet::DepthImage>("depth", "Input depth (uint16 mm).")
        .output<facet::DepthImage>("depth", "Shifted depth.")
        .param("offset_mm", 10, "Offset.", {.unit = "mm", .min = 0, .max = 1000})
        .concurrency(facet::Concurrency::clonable);
  }
  explicit AddOffset(const facet::Params& params)
      : offset_mm_(static_cast<int>(params.get_int("offset_mm"))) {}

  void process(facet::ProcessContext& ctx) override {
    const auto& in = ctx.input<facet::DepthImage>("depth");
    facet::DepthImage out = in;
    out.depth = in.depth.clone();
    cv::add(out.depth, cv::Scalar(offset_mm_), out.depth, in.depth > 0);
    ctx.output("depth", std::move(out));
    ctx.metric("offset_mm", offset_mm_);
  }

 private:
  int offset_mm_;
};

facet::Packet depth_packet(std::uint16_t value) {
  facet::DepthImage image;
  image.depth = cv::Mat(2, 2, CV_16UC1, cv::Scalar(value));
  image.depth.at<std::uint16_t>(0, 0) = 0;
  return facet::Packet::make(std::move(image));
}

TEST(StageRunner, RunsAStageWithoutAGraph) {
  facet::testing::StageRunner<AddOffset> runner({{"offset_mm", std::int64_t{5}}});
  runner.set_input("depth", depth_packet(100));
  runner.run();
  const auto& out = runner.output<facet::DepthImage>("depth");
  EXPECT_EQ(out.depth.at<std::uint16_t>(0, 0), 0);  // invalid stays invalid
  EXPECT_EQ(out.depth.at<std::uint16_t>(1, 1), 105);
  ASSERT_EQ(runner.metrics().size(), 1u);
  EXPECT_EQ(runner.metrics()[0].name, "offset_mm");
  EXPECT_DOUBLE_EQ(runner.metrics()[0].value, 5.0);
}

TEST(StageRunner, ChecksParametersLikeAGraph) {
  using Runner = facet::testing::StageRunner<AddOffset>;
  EXPECT_THROW(Runner({{"offset_mm", std::int64_t{5000}}}), std::invalid_argument);
  EXPECT_THROW(Runner({{"ofset_mm", std::int64_t{5}}}), std::invalid_argument);
  EXPECT_THROW(Runner({{"offset_mm", std::string("5")}}), std::invalid_argument);
}

TEST(StageRunner, MissingInputIsAStageError) {
  facet::testing::StageRunner<AddOffset> runner;
  EXPECT_THROW(runner.run(), facet::StageError);
}

TEST(ProcessContext, RefusesAnOutputOfTheWrongType) {
  const auto spec = AddOffset::spec();
  facet::ProcessContext ctx(spec, "node");
  EXPECT_THROW(ctx.output("depth", facet::LabelImage{}), std::logic_error);
  EXPECT_THROW(ctx.output("nope", facet::DepthImage{}), std::logic_error);
  EXPECT_THROW((void)ctx.input_packet("nope"), std::logic_error);
}

}  // namespace
