// Variant expansion: the product of the axes, each a merge patch of the base case.
#include <gtest/gtest.h>

#include "harness/variants.hpp"
#include "silodem/case/case_error.hpp"

using nlohmann::json;

TEST(Variants, ProductOfAxesWithPatchesApplied) {
  const json c = json::parse(R"({"time": {"dt": 1, "duration": 5}, "verify": {"variants": {
      "a": {"x": {"time": {"dt": 2}}, "y": {"time": {"dt": 3}}},
      "b": {"p": {"k": 1}, "q": {"k": null}}}}})");
  const auto v = harness::expand_variants(c);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[0].label, "a=x,b=p");
  EXPECT_EQ(v[3].label, "a=y,b=q");
  EXPECT_EQ(v[0].case_json["time"]["dt"], 2);
  EXPECT_EQ(v[0].case_json["time"]["duration"], 5);
  EXPECT_EQ(v[0].case_json["k"], 1);
  EXPECT_FALSE(v[3].case_json.contains("k"));
  EXPECT_EQ(harness::label_without(v[3], "a"), "b=q");
}

TEST(Variants, NoVariantsMeansTheBaseCase) {
  EXPECT_EQ(harness::expand_variants(json::parse(R"({"name": "x"})")).at(0).label, "base");
  EXPECT_THROW(harness::expand_variants(json::parse(R"({"verify": {"variants": {"a": {}}}})")), silodem::CaseError);
}
