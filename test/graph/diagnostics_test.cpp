#include <gtest/gtest.h>

#include <facet/framework/diagnostics.hpp>

namespace facet {
namespace {

TEST(GraphDiagnostics, FormatsLocationsLikeACompiler) {
  EXPECT_EQ(format_location({"g.yaml", 3, 7}), "g.yaml:3:7");
  EXPECT_EQ(format_location({"g.yaml", 3, 0}), "g.yaml:3");
  EXPECT_EQ(format_location({"<command line>", 0, 0}), "<command line>");
}

TEST(GraphDiagnostics, PrintsEveryItemInOrderAndCountsOnlyErrors) {
  Diagnostics diagnostics;
  diagnostics.error({"g.yaml", 2, 5}, "first");
  diagnostics.note({}, "context");
  diagnostics.warning({"g.yaml", 9, 1}, "later");
  diagnostics.error({kCommandLineFile, 0, 0}, "from an option");
  EXPECT_EQ(diagnostics.error_count(), 2);
  EXPECT_TRUE(diagnostics.has_errors());
  EXPECT_EQ(diagnostics.str(),
            "g.yaml:2:5: error: first\n"
            "note: context\n"
            "g.yaml:9:1: warning: later\n"
            "<command line>: error: from an option\n");
}

TEST(GraphDiagnostics, NoErrorsWhenOnlyNotesAndWarnings) {
  Diagnostics diagnostics;
  diagnostics.warning({"g.yaml", 1, 1}, "w");
  diagnostics.note({"g.yaml", 1, 1}, "n");
  EXPECT_FALSE(diagnostics.has_errors());
}

TEST(GraphDidYouMean, SuggestsTheClosestPlausibleName) {
  const std::vector<std::string> stages = {"filter.median", "normals.cross", "normals.pca"};
  EXPECT_EQ(did_you_mean("normals.crss", stages), "normals.cross");
  EXPECT_EQ(did_you_mean("filter.medain", stages), "filter.median");  // swapped letters
  EXPECT_EQ(did_you_mean("Normals.PCA", stages), "normals.pca");      // case only
}

TEST(GraphDidYouMean, StaysQuietForUnrelatedNames) {
  const std::vector<std::string> stages = {"filter.median", "normals.cross"};
  EXPECT_EQ(did_you_mean("planes.ransac", stages), "");
  EXPECT_EQ(did_you_mean("", stages), "");
  EXPECT_EQ(did_you_mean("x", {}), "");
}

// A 10 MB stage name took 1.8 GB in the edit distance; names longer than anything typed get no
// suggestion, and candidates far longer or shorter are ruled out by their length alone.
TEST(GraphDidYouMean, ANameLongerThanAnyIdentifierGetsNoSuggestion) {
  const std::string huge(10'000'000, 'a');
  EXPECT_EQ(did_you_mean(huge, {huge.substr(1), "normals.cross"}), "");
  std::vector<std::string> many;
  for (int i = 0; i < 100'000; ++i)
    many.push_back("param_number_" + std::to_string(i));
  many.push_back("output");
  EXPECT_EQ(did_you_mean("ouptut", many), "output");
  EXPECT_EQ(did_you_mean("param_numbr_99999", many), "param_number_99999");
}

TEST(GraphDidYouMean, BreaksTiesByCandidateOrder) {
  EXPECT_EQ(did_you_mean("sise", {"size", "site"}), "size");
  EXPECT_EQ(did_you_mean("sise", {"site", "size"}), "site");
}

}  // namespace
}  // namespace facet
