// Material tests taken from an earlier verify: the spread rows of silodem come back with their
// group, mean, scatter and realisations, as report rows; other rows, other codes' rows and groups
// without a value are left; a file that is not an earlier verify's verdicts.json is refused by name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "harness/janssen_prediction.hpp"
#include "harness/taken_rows.hpp"
#include "silodem/case/case_error.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p;
}

}  // namespace

TEST(TakenRows, TheSpreadRowsOfAnEarlierVerifyComeBackAsTheMaterialTests) {
  const json rows = json::array({
      {{"case", "direct_shear"}, {"variant", "mu=0.5,rolling=none"}, {"code", "silodem"},
       {"quantity", "internal_friction_critical_deg_spread"}, {"subject", "plane"}, {"expected", 23.86},
       {"measured", 0.29}, {"note", "3 realisations (seed)"}},
      {{"case", "direct_shear"}, {"variant", "mu=0.5,rolling=none,seed=2002"}, {"code", "silodem"},
       {"quantity", "internal_friction_critical_deg"}, {"expected", nullptr}, {"measured", 23.5}, {"note", ""}},
      {{"case", "wall_friction"}, {"variant", "mu=0.5,rolling=none"}, {"code", "silodem"},
       {"quantity", "wall_friction_mu_w_spread"}, {"expected", 0.270}, {"measured", 0.0039}, {"note", "3 realisations"}},
      {{"case", "wall_friction"}, {"variant", "mu=0.3,rolling=none"}, {"code", "silodem"},
       {"quantity", "wall_friction_mu_w_spread"}, {"expected", nullptr}, {"measured", nullptr}, {"note", ""}},
      {{"case", "wall_friction"}, {"variant", "mu=0.5,rolling=none"}, {"code", "lammps"},
       {"quantity", "wall_friction_mu_w_spread"}, {"expected", 0.9}, {"measured", 0.1}, {"note", ""}}});
  const fs::path f = write("silodem_test_taken_rows.json", json{{"rows", rows}}.dump());
  const auto taken = harness::read_spread_rows(f);
  ASSERT_EQ(taken.size(), 2u);
  for (const auto& r : taken) {
    EXPECT_EQ(r.verdict(), "report");
    EXPECT_FALSE(r.judged());
  }
  // They serve a check exactly as the rows of the same run would.
  const auto phi = harness::measured_parameter(taken, "direct_shear", "internal_friction_critical_deg",
                                               "mu=0.5,rolling=none,beta=35");
  EXPECT_EQ(phi.mean, 23.86);
  EXPECT_EQ(phi.scatter, 0.29);
  EXPECT_EQ(phi.realisations, 3);
  EXPECT_EQ(harness::measured_parameter(taken, "wall_friction", "wall_friction_mu_w", "mu=0.5,rolling=none").mean, 0.270);
  EXPECT_THROW(harness::measured_parameter(taken, "wall_friction", "wall_friction_mu_w", "mu=0.3,rolling=none"),
               std::runtime_error);
}

TEST(TakenRows, AFileThatIsNotAnEarlierVerifysVerdictsIsRefusedByName) {
  const fs::path missing = fs::temp_directory_path() / "silodem_test_taken_rows_missing.json";
  fs::remove(missing);
  const fs::path not_json = write("silodem_test_taken_rows_bad.json", "{rows: [");
  const fs::path no_rows = write("silodem_test_taken_rows_norows.json", "{\"cases\": []}");
  const fs::path no_spread = write("silodem_test_taken_rows_nospread.json",
                                   "{\"rows\": [{\"case\": \"a\", \"code\": \"silodem\", \"quantity\": \"restitution\"}]}");
  for (const fs::path& f : {missing, not_json, no_rows, no_spread}) {
    try {
      harness::read_spread_rows(f);
      ADD_FAILURE() << f << " was accepted";
    } catch (const silodem::CaseError& e) {
      EXPECT_NE(std::string(e.what()).find(f.string()), std::string::npos) << e.what();
    }
  }
}
