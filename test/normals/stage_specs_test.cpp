// Every port and parameter of the normals and convert stages is documented, with the origin of
// every default, and the stages can run on several frames at once.
#include <gtest/gtest.h>

#include "convert/points_stage.hpp"
#include "normals/cross_stage.hpp"
#include "normals/pca_stage.hpp"
#if defined(FACET_HAVE_PCL_NORMALS)
#include "normals/pcl/integral_stage.hpp"
#endif

namespace {

std::vector<facet::StageSpec> specs() {
  std::vector<facet::StageSpec> all{facet::convert::PointsStage::spec(),
                                    facet::normals::CrossStage::spec(),
                                    facet::normals::PcaStage::spec()};
#if defined(FACET_HAVE_PCL_NORMALS)
  all.push_back(facet::normals::IntegralStage::spec());
#endif
  return all;
}

TEST(NormalStageSpecs, EverythingDocumented) {
  for (const auto& spec : specs()) {
    EXPECT_FALSE(spec.summary().empty()) << spec.name();
    EXPECT_EQ(spec.concurrency(), facet::Concurrency::clonable) << spec.name();
    for (const auto& port : spec.inputs())
      EXPECT_FALSE(port.doc.empty()) << spec.name();
    for (const auto& port : spec.outputs())
      EXPECT_FALSE(port.doc.empty()) << spec.name();
    for (const auto& param : spec.params()) {
      EXPECT_FALSE(param.doc.empty()) << spec.name() << "." << param.name;
      EXPECT_FALSE(param.options.origin.empty()) << spec.name() << "." << param.name;
      const bool numeric =
          param.type == facet::ParamType::integer || param.type == facet::ParamType::real;
      if (numeric) {
        EXPECT_TRUE(param.options.min && param.options.max) << spec.name() << "." << param.name;
      }
      if (param.type == facet::ParamType::string) {
        EXPECT_FALSE(param.options.choices.empty()) << spec.name() << "." << param.name;
      }
    }
  }
}

TEST(NormalStageSpecs, PaperDefaults) {
  const auto cross = facet::normals::CrossStage::spec().default_params();
  EXPECT_EQ(cross.get_int("radius"), 2);
  EXPECT_EQ(cross.get_string("triangle"), "paper");
  EXPECT_EQ(cross.get_string("space"), "image");
  EXPECT_EQ(cross.get_int("smooth_radius"), 0);
  EXPECT_FALSE(cross.get_bool("renormalize"));
}

}  // namespace
