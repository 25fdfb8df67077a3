// Variant expansion: the product of the axes, each a merge patch of the base case.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "harness/variants.hpp"
#include "harness/verify.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/memory_estimate.hpp"

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

namespace {
/// The CaseError path and message of expanding `verify.variants` = `axes`, or "accepted".
std::string expand_error(const json& axes, const json& extra = json::object()) {
  json c = extra;
  c["verify"]["variants"] = axes;
  try {
    harness::expand_variants(c);
  } catch (const silodem::CaseError& e) {
    return e.what();
  }
  return "accepted";
}
json axis_of(int values) {
  json a = json::object();
  for (int i = 0; i < values; ++i) a["v" + std::to_string(i)] = json::object();
  return a;
}
}  // namespace

TEST(Variants, AtMostAThousandRunsCountedBeforeAnyIsBuilt) {
  EXPECT_EQ(expand_error({{"a", axis_of(10)}, {"b", axis_of(10)}, {"c", axis_of(10)}}), "accepted");
  const std::string e = expand_error({{"a", axis_of(7)}, {"b", axis_of(11)}, {"c", axis_of(13)}});
  EXPECT_EQ(e.rfind("$.verify.variants: the axes make 1001 runs, more than the 1000", 0), 0u) << e;
  // 40 axes of 10 values would be 10^40 runs: refused at once, not after running out of memory.
  json huge = json::object();
  for (int i = 0; i < 40; ++i) huge["axis" + std::to_string(i)] = axis_of(10);
  EXPECT_NE(expand_error(huge).find("more than the 1000"), std::string::npos);
}

TEST(Variants, NamesMustMakeOneDistinctDirectoryPerVariant) {
  EXPECT_EQ(expand_error({{"dt", {{"tc 50", json::object()}, {"tc_100", json::object()}}}}), "accepted");
  EXPECT_EQ(expand_error({{"dt", {{"..", json::object()}}}}).rfind("$.verify.variants.dt...: the name \"..\"", 0), 0u);
  EXPECT_NE(expand_error({{"a/b", axis_of(1)}}).find("$.verify.variants.a/b: the name \"a/b\""), std::string::npos);
  EXPECT_NE(expand_error({{"dt", {{"x,y", json::object()}}}}).find("may not contain ',' or '='"), std::string::npos);
  EXPECT_NE(expand_error({{"d=t", axis_of(1)}}).find("may not contain ',' or '='"), std::string::npos);
  // ' ' is written '-' in the directory name: "tc 50" and "tc-50" would share one.
  EXPECT_NE(expand_error({{"dt", {{"tc 50", json::object()}, {"tc-50", json::object()}}}})
                .find("dt=tc 50 and dt=tc-50 would write to the same directory \"dt=tc-50\""),
            std::string::npos);
  // Each name within 100 bytes, the label of three such axes not within 200.
  const std::string n99(99, 'n');
  const json long_axes = {{"a" + n99, {{"x" + n99, json::object()}}}, {"b" + n99, {{"y" + n99, json::object()}}}};
  EXPECT_NE(expand_error(long_axes).find("would write to a directory name of 403 bytes (at most 200)"), std::string::npos)
      << expand_error(long_axes);
}

TEST(Variants, AllTheirCopiesMustFitBesideARun) {
  // A thousand variants, each kept as JSON and as a loaded case: a case whose parsed JSON is a
  // thousandth of a quarter of the limit is refused, one a hundredth of that is accepted.
  const double limit = silodem::run_memory_limit().bytes;
  const json axes = {{"a", axis_of(10)}, {"b", axis_of(10)}, {"c", axis_of(10)}};
  const auto with_text = [](double bytes) { return json{{"description", std::string(std::size_t(bytes), 'x')}}; };
  const std::string e = expand_error(axes, with_text(1.1 * limit / 4000.0));
  EXPECT_EQ(e.rfind("$.verify.variants: the 1000 variants would hold ", 0), 0u) << e;
  EXPECT_EQ(expand_error(axes, with_text(0.01 * limit / 4000.0)), "accepted");
}
