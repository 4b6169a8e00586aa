// Typed contracts (facet/contract.hpp): one descriptor declares a port or parameter in the spec
// and reads it back, and a structured parameter's parser runs wherever values are checked.
#include "facet/contract.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cstdint>
#include <string>
#include <variant>

#include "facet/stage.hpp"
#include "facet/testing/stage_runner.hpp"
#include "facet/types/images.hpp"

namespace facet::contract_test {

// A structured value: an interval written "lo..hi".
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  bool operator==(const Interval&) const = default;
};

}  // namespace facet::contract_test

template <>
struct facet::ParamTraits<facet::contract_test::Interval> {
  static std::variant<contract_test::Interval, std::string> parse(std::string_view text) {
    const auto dots = text.find("..");
    if (dots == std::string_view::npos) return "expected 'lo..hi', got '" + std::string(text) + "'";
    contract_test::Interval interval;
    const auto lo = text.substr(0, dots);
    const auto hi = text.substr(dots + 2);
    if (std::from_chars(lo.data(), lo.data() + lo.size(), interval.lo).ec != std::errc() ||
        std::from_chars(hi.data(), hi.data() + hi.size(), interval.hi).ec != std::errc()) {
      return "expected two numbers in 'lo..hi', got '" + std::string(text) + "'";
    }
    if (interval.hi < interval.lo) return std::string("the interval ends before it starts");
    return interval;
  }
  static std::string format(const contract_test::Interval& interval) {
    return std::to_string(interval.lo) + ".." + std::to_string(interval.hi);
  }
};

namespace facet::contract_test {
namespace {

enum class Mode { fast, exact };

const In<DepthImage> kDepth{"depth", "Depth in."};
const OptionalIn<LabelImage> kHint{"hint", "Labels, optional."};
const Out<DepthImage> kForwarded{"forwarded", "The input, forwarded."};
const Out<LabelImage> kLabels{"labels", "Labels out."};
const Param<int> kSize{"size", 3, "Window side.", {.unit = "px", .min = 1.0, .max = 99.0}};
const Param<double> kThreshold{"threshold", 0.5, "A threshold.", {.min = 0.0, .max = 1.0}};
const Param<bool> kVerbose{"verbose", false, "Talk more."};
const Param<std::string> kTag{"tag", "none", "Free text."};
const Param<std::int64_t> kBig{"big", std::int64_t{1} << 40, "A wide integer."};
const EnumParam<Mode> kMode{
    "mode", Mode::exact, {{Mode::fast, "fast"}, {Mode::exact, "exact"}}, "How."};
const Param<Interval> kRange{"range", Interval{0.5, 2.0}, "Where, 'lo..hi'."};

class ContractStage final : public Stage {
 public:
  static StageSpec spec() {
    StageSpec spec("test.contract", "Reads every kind of descriptor.");
    return spec.declare(kDepth, kHint, kForwarded, kLabels, kSize, kThreshold, kVerbose, kTag, kBig,
                        kMode, kRange);
  }
  explicit ContractStage(const Params& params)
      : size_(kSize(params)),
        threshold_(kThreshold(params)),
        mode_(kMode(params)),
        range_(kRange(params)) {}

  void process(ProcessContext& ctx) override {
    kForwarded.forward(ctx, kDepth.packet(ctx));
    const DepthImage& depth = kDepth(ctx);
    const LabelImage* hint = kHint(ctx);
    const int count = hint != nullptr ? hint->count : size_;
    LabelImage labels =
        LabelImage::make(depth, cv::Mat::zeros(depth.depth.size(), CV_32SC1), count);
    ctx.metric("exact", mode_ == Mode::exact ? 1.0 : 0.0);
    ctx.metric("threshold", threshold_);
    ctx.metric("range_width", range_.hi - range_.lo);
    kLabels(ctx, std::move(labels));
  }

 private:
  int size_;
  double threshold_;
  Mode mode_;
  Interval range_;
};

double metric(const testing::StageRunner<ContractStage>& runner, std::string_view name) {
  for (const auto& m : runner.metrics()) {
    if (m.name == name) return m.value;
  }
  ADD_FAILURE() << "no metric " << name;
  return 0.0;
}

TEST(Contract, DescriptorsBuildTheSpecInOrder) {
  const StageSpec spec = ContractStage::spec();
  ASSERT_EQ(spec.inputs().size(), 2u);
  EXPECT_EQ(spec.inputs()[0].name, "depth");
  EXPECT_TRUE(spec.inputs()[0].required);
  EXPECT_EQ(spec.inputs()[0].type_key, type_key<DepthImage>());
  EXPECT_EQ(spec.inputs()[1].name, "hint");
  EXPECT_FALSE(spec.inputs()[1].required);
  ASSERT_EQ(spec.outputs().size(), 2u);
  EXPECT_EQ(spec.outputs()[1].type_key, type_key<LabelImage>());

  std::vector<std::string> names;
  for (const auto& p : spec.params())
    names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"size", "threshold", "verbose", "tag", "big", "mode",
                                             "range"}));
  const ParamSpec& size = *spec.find_param("size");
  EXPECT_EQ(size.type, ParamType::integer);
  EXPECT_EQ(size.default_value, ParamValue(std::int64_t{3}));
  EXPECT_EQ(size.options.unit, "px");
  const ParamSpec& mode = *spec.find_param("mode");
  EXPECT_EQ(mode.type, ParamType::string);
  EXPECT_EQ(mode.default_value, ParamValue(std::string("exact")));
  EXPECT_EQ(mode.options.choices,
            (std::vector<ParamValue>{std::string("fast"), std::string("exact")}));
  const ParamSpec& range = *spec.find_param("range");
  EXPECT_EQ(range.type, ParamType::string);
  EXPECT_EQ(range.default_value, ParamValue(ParamTraits<Interval>::format({0.5, 2.0})));
}

TEST(Contract, DescriptorsReadValuesAndPorts) {
  testing::StageRunner<ContractStage> runner(
      {{"mode", std::string("fast")}, {"threshold", 0.25}, {"range", std::string("1..4")}});
  DepthImage depth;
  depth.depth = cv::Mat(2, 3, CV_16UC1, cv::Scalar(500));
  runner.set_input("depth", Packet::make(depth));
  runner.run();
  EXPECT_EQ(metric(runner, "exact"), 0.0);
  EXPECT_EQ(metric(runner, "threshold"), 0.25);
  EXPECT_EQ(metric(runner, "range_width"), 3.0);
  EXPECT_EQ(runner.output<LabelImage>("labels").count, 3);  // no hint: the window size

  LabelImage hint;
  hint.labels = cv::Mat::zeros(2, 3, CV_32SC1);
  hint.count = 7;
  runner.set_input("hint", Packet::make(hint));
  runner.run();
  EXPECT_EQ(runner.output<LabelImage>("labels").count, 7);
}

TEST(Contract, ForwardingSharesThePayload) {
  testing::StageRunner<ContractStage> runner;
  DepthImage depth;
  depth.depth = cv::Mat(2, 3, CV_16UC1, cv::Scalar(500));
  const Packet input = Packet::make(depth);
  runner.set_input("depth", input);
  runner.run();
  EXPECT_EQ(&runner.output<DepthImage>("forwarded"), input.get_if<DepthImage>());
}

TEST(Contract, ForwardingAPacketOfAnotherTypeIsAProgrammingError) {
  const StageSpec spec = ContractStage::spec();
  ProcessContext ctx(spec, "node");
  ctx.begin_frame(0);
  EXPECT_THROW(kForwarded.forward(ctx, Packet::make(LabelImage{})), std::logic_error);
}

TEST(Contract, AMissingRequiredInputNamesThePort) {
  testing::StageRunner<ContractStage> runner;
  try {
    runner.run();
    FAIL() << "no error";
  } catch (const StageError& error) {
    EXPECT_NE(std::string(error.what()).find("depth"), std::string::npos) << error.what();
  }
}

TEST(Contract, AStructuredValueIsCheckedByItsParser) {
  const StageSpec spec = ContractStage::spec();
  const ParamSpec& range = *spec.find_param("range");
  EXPECT_FALSE(check_param_value(range, std::string("0..1")).has_value());
  const auto no_dots = check_param_value(range, std::string("0-1"));
  ASSERT_TRUE(no_dots.has_value());
  EXPECT_NE(no_dots->find("lo..hi"), std::string::npos) << *no_dots;
  const auto backwards = check_param_value(range, std::string("3..1"));
  ASSERT_TRUE(backwards.has_value());
  EXPECT_NE(backwards->find("ends before it starts"), std::string::npos) << *backwards;
  // The runner validates like `facet validate`: the stage is never built with a bad value.
  EXPECT_THROW(testing::StageRunner<ContractStage>({{"range", std::string("x")}}),
               std::invalid_argument);
}

TEST(Contract, AnIntParameterMustFitAnInt) {
  const StageSpec spec = ContractStage::spec();
  const ParamSpec& size = *spec.find_param("size");
  ParamSpec unbounded = size;
  unbounded.options.min.reset();
  unbounded.options.max.reset();
  EXPECT_FALSE(check_param_value(unbounded, std::int64_t{2147483647}).has_value());
  const auto error = check_param_value(unbounded, std::int64_t{2147483648});
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("32-bit"), std::string::npos) << *error;
  // std::int64_t parameters take the whole range.
  EXPECT_FALSE(check_param_value(*spec.find_param("big"), std::int64_t{1} << 50).has_value());
}

TEST(Contract, AnEnumTakesOnlyItsNames) {
  const StageSpec spec = ContractStage::spec();
  const auto error = check_param_value(*spec.find_param("mode"), std::string("slow"));
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("fast, exact"), std::string::npos) << *error;
  EXPECT_EQ(kMode.name_of(Mode::fast), "fast");
}

TEST(Contract, ADefaultThatFailsItsOwnCheckIsABugReportedAtDeclaration) {
  const Param<Interval> backwards{"range", Interval{2.0, 1.0}, "Backwards."};
  StageSpec spec("test.bad_default", "A stage whose default is invalid.");
  EXPECT_THROW(spec.declare(backwards), std::logic_error);
}

}  // namespace
}  // namespace facet::contract_test
