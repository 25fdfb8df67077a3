// The closure check on pressure histories whose rise is known: a band loaded at 200 Pa that
// rises to 300 Pa on average with one spike of 500 Pa gives back 1.5 and 2.5; a band at the fill's
// surface that goes from 2 Pa to 6 Pa (a ratio of 3, of a few touching grains) does not count.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "harness/silo_checks.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kClose = 0.5;

/// band0: 200 Pa, then 300 Pa after the closure with one sample of 500 Pa 2 ms after it;
/// band1: 100 Pa throughout; band2 (the surface): 2 Pa, then 6 Pa.
harness::ResultSet closure_history(const fs::path& dir) {
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir / "probes");
  std::ofstream csv(dir / "probes" / "hopper_history.csv");
  csv.precision(17);
  csv << "t,band0,band1,band2\n";
  for (int i = 0; i <= 100; ++i) {  // every millisecond from 0.45 to 0.55 s
    const double t = 0.45 + 0.001 * i;
    const bool after = t > kClose + 1e-9;
    const double b0 = !after ? 200.0 : (i == 52 ? 500.0 : 300.0);
    csv << t << ',' << b0 << ",100," << (after ? 6.0 : 2.0) << '\n';
  }
  csv.close();
  return {dir, {{"probes", {{"hopper", {{"history_file", "hopper_history.csv"}}}}}}};
}

double row(const std::vector<harness::CheckRow>& rows, const std::string& q) {
  for (const auto& r : rows)
    if (r.quantity == q) return r.measured;
  return NAN;
}

}  // namespace

TEST(ClosureOverpressure, GivesTheRiseOfTheLoadedBandsAndIgnoresTheSurface) {
  const silodem::CaseConfig cfg;
  const auto rs = closure_history(fs::temp_directory_path() / "silodem_test_closure");
  const harness::RunContext ctx{cfg, rs, "v"};
  const json spec = {{"wall_probe", "hopper"}, {"close_time", kClose}, {"window", 0.03}};
  const auto rows = harness::closure_overpressure(spec, ctx);
  // 30 samples after the closure: 29 at 300 Pa and one at 500 Pa.
  EXPECT_NEAR(row(rows, "closure_mean_post/pre_pressure"), (29 * 300.0 + 500.0) / 30 / 200.0, 1e-12);
  EXPECT_NEAR(row(rows, "closure_peak/pre_pressure"), 2.5, 1e-12);
  for (const auto& r : rows) {
    EXPECT_NE(r.note.find("band 0"), std::string::npos) << r.note;
    EXPECT_EQ(r.verdict(), "report") << r.quantity;  // no min_rise_source: nothing to judge against
  }
}
