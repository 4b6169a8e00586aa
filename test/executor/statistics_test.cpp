#include "facet/framework/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "facet/framework/json_writer.hpp"

namespace {

TEST(Statistics, MedianAndPercentiles) {
  EXPECT_DOUBLE_EQ(facet::median({}), 0.0);
  EXPECT_DOUBLE_EQ(facet::median({3.0}), 3.0);
  EXPECT_DOUBLE_EQ(facet::median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_DOUBLE_EQ(facet::median({4.0, 1.0, 3.0, 2.0}), 2.5);
  std::vector<double> hundred;
  for (int i = 1; i <= 101; ++i)
    hundred.push_back(i);
  EXPECT_DOUBLE_EQ(facet::percentile(hundred, 95.0), 96.0);
  EXPECT_DOUBLE_EQ(facet::percentile(hundred, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(facet::percentile(hundred, 100.0), 101.0);
}

TEST(JsonWriter, WritesNestedValuesWithEscaping) {
  std::ostringstream out;
  facet::JsonWriter json(out, 0);
  json.begin_object();
  json.key("name").value("a \"quoted\"\nline");
  json.key("n").value(std::int64_t{3});
  json.key("x").value(0.5);
  json.key("nan").value(std::nan(""));
  json.key("list").begin_array().value(true).value(false).end_array();
  json.key("empty").begin_object().end_object();
  json.end_object();
  EXPECT_EQ(
      out.str(),
      R"({"name":"a \"quoted\"\nline","n":3,"x":0.5,"nan":null,"list":[true,false],"empty":{}})");
}

}  // namespace
