// Variant expansion: the product of the axes, each a merge patch of the base case.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "harness/variants.hpp"
#include "harness/verify.hpp"
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
  EXPECT_EQ(harness::expand_variants(json::parse(R"({"verify": {"variants": {}}})")).at(0).label, "base");
  EXPECT_THROW(harness::expand_variants(json::parse(R"({"verify": {"variants": {"a": {}}}})")), silodem::CaseError);
}

TEST(VerifyValidation, ChecksMustReferToWhatExists) {
  // The free-fall case with one reference broken at a time: each is refused with its JSON path.
  std::ifstream in(std::string(SILODEM_SOURCE_DIR) + "/cases/free_fall_contact.json");
  const json base = json::parse(in);
  const auto path_of = [&](const std::string& pointer, const json& value) {
    json c = base;
    c[json::json_pointer(pointer)] = value;
    const auto f = std::filesystem::temp_directory_path() / "silodem_verify_validation.json";
    std::ofstream(f) << c.dump();
    try {
      harness::validate_verification(f);
    } catch (const silodem::CaseError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(path_of("/seed", 2), "accepted");
  EXPECT_NE(path_of("/verify/checks/0/obstacle", "nosuch").find("$.verify.checks[0].obstacle"), std::string::npos);
  EXPECT_NE(path_of("/verify/checks/0/drop", 5).find("$.verify.checks[0].drop"), std::string::npos);
  EXPECT_NE(path_of("/verify/checks/0/twin/pair_probe", "bouncer").find("twin.pair_probe"), std::string::npos);
  EXPECT_NE(path_of("/verify/checks/1/tolerance", -1).find("$.verify.checks[1].tolerance"), std::string::npos);
  EXPECT_NE(path_of("/verify/checks/2", json{{"type", "convergence"}, {"axis", "dtt"}}).find("axis"), std::string::npos);
  EXPECT_NE(path_of("/verify/variants/integrator/pc_explicit/integrator/scheme", "rk4").find("in variant"),
            std::string::npos);
}
