// Finding stages by filter, family and plugin, the names suggested for a typo, and a stage's spec
// as JSON (`facet list FILTER`, `facet inspect FAMILY|PLUGIN`, `facet inspect --json`).
#include "facet/framework/stage_catalogue.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "facet/framework/json_writer.hpp"
#include "facet/framework/stage_doc.hpp"
#include "test_stages.hpp"

namespace facet::graph_test {
namespace {

// Two plugins, as the loader would register them.
Registry two_plugins() {
  Registry registry;
  auto io = std::make_shared<PluginInfo>();
  io->name = "facet_io";
  io->version = "1.2.0";
  io->file = "plugins/libfacet_io.so";
  io->stages = {"io.frames", "io.depth"};
  StageList io_stages;
  io_stages.add<FramesSource>();
  io_stages.add<DepthWriter>();
  registry.add_plugin(io, io_stages.stages(), nullptr);
  auto normals = std::make_shared<PluginInfo>();
  normals->name = "facet_normals";
  normals->version = "1.2.0";
  normals->stages = {"normals.cross", "normals.pca", "normals.points"};
  StageList normal_stages;
  normal_stages.add<CrossNormals>();
  normal_stages.add<PcaNormals>();
  normal_stages.add<PointNormals>();
  registry.add_plugin(normals, normal_stages.stages(), nullptr);
  return registry;
}

std::vector<std::string> names_of(const std::vector<const StageEntry*>& entries) {
  std::vector<std::string> names;
  for (const StageEntry* entry : entries)
    names.push_back(entry->spec.name());
  return names;
}

using Names = std::vector<std::string>;

TEST(StageCatalogue, FilterMatchesNamePluginAndSummaryIgnoringCase) {
  const Registry registry = two_plugins();
  EXPECT_EQ(names_of(stages_matching(registry, "NORMALS")),
            (Names{"normals.cross", "normals.pca", "normals.points"}));
  EXPECT_EQ(names_of(stages_matching(registry, "facet_io")), (Names{"io.depth", "io.frames"}));
  // "Reads recorded depth frames." and "Normals from local PCA."
  EXPECT_EQ(names_of(stages_matching(registry, "recorded")), (Names{"io.frames"}));
  EXPECT_EQ(names_of(stages_matching(registry, "local pca")), (Names{"normals.pca"}));
  EXPECT_EQ(stages_matching(registry, "").size(), 5u);
  EXPECT_TRUE(stages_matching(registry, "superquadric").empty());
}

TEST(StageCatalogue, FamiliesAndPlugins) {
  const Registry registry = two_plugins();
  EXPECT_EQ(stage_family("normals.cross"), "normals");
  EXPECT_EQ(stage_family("plain"), "plain");
  EXPECT_EQ(names_of(stages_of_family(registry, "normals")),
            (Names{"normals.cross", "normals.pca", "normals.points"}));
  EXPECT_TRUE(stages_of_family(registry, "normal").empty());  // a family, not a prefix
  EXPECT_TRUE(stages_of_family(registry, "normals.cross").empty());
  ASSERT_NE(find_plugin(registry, "facet_io"), nullptr);
  EXPECT_EQ(find_plugin(registry, "facet_io")->version, "1.2.0");
  EXPECT_EQ(find_plugin(registry, "facet_i"), nullptr);
}

TEST(StageCatalogue, SuggestsStagesFamiliesPluginsAndForListsTheirWords) {
  const Registry registry = two_plugins();
  EXPECT_EQ(closest_catalogue_names(registry, "normls", 3, CatalogueNames::inspectable),
            (Names{"normals"}));
  EXPECT_EQ(closest_catalogue_names(registry, "facet_normal", 3, CatalogueNames::inspectable),
            (Names{"facet_normals"}));
  const Names cross =
      closest_catalogue_names(registry, "normals.crss", 3, CatalogueNames::inspectable);
  ASSERT_FALSE(cross.empty());
  EXPECT_EQ(cross.front(), "normals.cross");
  // "frames" is a good filter for `facet list`, but `facet inspect frames` would not find it.
  EXPECT_TRUE(closest_catalogue_names(registry, "frmes", 3, CatalogueNames::inspectable).empty());
  EXPECT_EQ(closest_catalogue_names(registry, "frmes", 3, CatalogueNames::filter_words),
            (Names{"frames"}));
  EXPECT_TRUE(
      closest_catalogue_names(registry, "zzzzzzzz", 3, CatalogueNames::filter_words).empty());
  // At most `count`, closest first.
  const Names io = closest_catalogue_names(registry, "iox", 3, CatalogueNames::filter_words);
  ASSERT_FALSE(io.empty());
  EXPECT_EQ(io.front(), "io");
  EXPECT_LE(closest_catalogue_names(registry, "pca", 1, CatalogueNames::filter_words).size(), 1u);
}

TEST(StageCatalogue, SpecAsJsonHasEveryAttributeAndNullWhereAbsent) {
  const Registry registry = two_plugins();
  std::ostringstream out;
  JsonWriter json(out);
  write_stage_json(json, *registry.find("io.frames"));
  const std::string text = out.str();
  for (const char* expected : {
           "\"name\": \"io.frames\"",
           "\"summary\": \"Reads recorded depth frames.\"",
           "\"plugin\": {\n    \"name\": \"facet_io\",\n    \"version\": \"1.2.0\",\n    \"file\": "
           "\"plugins/libfacet_io.so\"\n  }",
           "\"concurrency\": \"serial\"",
           "\"inputs\": []",
           "\"type_key\": \"facet.DepthImage/1\"",
           // path: required string without range or unit
           "\"name\": \"path\",\n      \"type\": \"string\",\n      \"required\": true,\n      "
           "\"default\": \"\",\n      \"min\": null,\n      \"max\": null,\n      \"choices\": "
           "null,\n      \"unit\": null,\n      \"doc\": \"Directory of the recording.\",\n     "
           " \"default_origin\": null",
           // fps: a real with a lower bound and a unit
           "\"name\": \"fps\",\n      \"type\": \"real\",\n      \"required\": false,\n      "
           "\"default\": 30,\n      \"min\": 0,\n      \"max\": null",
           "\"unit\": \"Hz\"",
           "\"name\": \"loop\",\n      \"type\": \"bool\",\n      \"required\": false,\n      "
           "\"default\": false",
       }) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
  }
  std::ostringstream median_out;
  StageList median;
  median.add<MedianFilter>();
  Registry builtin;
  builtin.add_builtin(median.stages());
  JsonWriter median_json(median_out);
  write_stage_json(median_json, *builtin.find("filter.median"));
  EXPECT_NE(median_out.str().find("\"file\": null"), std::string::npos) << median_out.str();
  EXPECT_NE(median_out.str().find("\"type\": \"int\""), std::string::npos) << median_out.str();
  EXPECT_NE(median_out.str().find("\"choices\": [\n        3,\n        5\n      ]"),
            std::string::npos)
      << median_out.str();
}

}  // namespace
}  // namespace facet::graph_test
