// Every io stage documents its ports and parameters completely (what `facet inspect` shows).
#include <gtest/gtest.h>

#include "facet/plugin.hpp"
#include "io/depth_sink.hpp"
#include "io/edges_sink.hpp"
#include "io/frames_source.hpp"
#include "io/labels_sink.hpp"

namespace {

std::vector<facet::StageSpec> all_specs() {
  facet::StageList list;
  list.add<facet::io::FramesSource>();
  list.add<facet::io::LabelsSink>();
  list.add<facet::io::DepthSink>();
  list.add<facet::io::EdgesSink>();
  return list.stages();
}

TEST(StageSpecs, EveryPortAndParameterIsDocumented) {
  for (const auto& spec : all_specs()) {
    SCOPED_TRACE(spec.name());
    EXPECT_FALSE(spec.summary().empty());
    for (const auto& port : spec.inputs())
      EXPECT_FALSE(port.doc.empty()) << port.name;
    for (const auto& port : spec.outputs())
      EXPECT_FALSE(port.doc.empty()) << port.name;
    for (const auto& param : spec.params()) {
      EXPECT_FALSE(param.doc.empty()) << param.name;
      const bool numeric =
          param.type == facet::ParamType::integer || param.type == facet::ParamType::real;
      if (numeric) {
        EXPECT_FALSE(param.options.unit.empty()) << param.name << " has no unit";
      }
    }
  }
}

TEST(StageSpecs, NamesKindsAndConcurrency) {
  const auto specs = all_specs();
  ASSERT_EQ(specs.size(), 4U);
  EXPECT_EQ(specs[0].name(), "io.frames");
  EXPECT_TRUE(specs[0].is_source());
  EXPECT_EQ(specs[0].concurrency(), facet::Concurrency::serial);
  EXPECT_TRUE(specs[0].find_param("path")->options.required);
  EXPECT_EQ(specs[1].name(), "io.labels");
  EXPECT_TRUE(specs[1].outputs().empty());
  EXPECT_EQ(specs[2].name(), "io.depth");
  EXPECT_EQ(specs[3].name(), "io.edges");
  EXPECT_TRUE(specs[3].outputs().empty());
}

}  // namespace
