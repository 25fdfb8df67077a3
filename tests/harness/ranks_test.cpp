// LAMMPS and LIGGGHTS under MPI (issue 31 §2): 64 frictional grains (Hertz–Mindlin, clamped) drop
// onto a floor of wall balls and pile up, 0.1 s, on one rank and on two (mpirun -np 2; the box is
// split through the pile). The same physics on any rank count: the final kinetic and gravitational
// energies, rebuilt from each run's dump, agree to 1e-12 (measured: bitwise), and each summary
// records its rank count and launcher command.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/backends/subprocess.hpp"
#include "harness/compare.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json pile() {
  json balls = json::array();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        balls.push_back({{"id", "g" + std::to_string(16 * i + 4 * j + k)}, {"material", "grain"}, {"radius", 0.005},
                         {"position", {-0.0165 + 0.011 * i + 0.0005 * k, -0.0165 + 0.011 * j, 0.012 + 0.011 * k}}});
  return {{"format", "silodem-case/1"},
          {"name", "ranks_pile"},
          {"gravity", {0, 0, -9.81}},
          {"contact", {{"normal", "hertz"}, {"tangential", "mindlin"}, {"clamp_tensile_force", true}}},
          {"materials",
           {{"grain", {{"density", 2500}, {"youngs_modulus", 1e8}, {"poisson_ratio", 0.25}, {"restitution", 0.5}, {"friction", 0.4}}},
            {"steel", {{"density", 7800}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}, {"restitution", 0.5}, {"friction", 0.4}}}}},
          {"walls", {{{"name", "floor"}, {"type", "disk"}, {"material", "steel"}, {"radius", {0.005, 0.005}},
                      {"spacing", 0.006}, {"centre", {0, 0, 0}}, {"diameter", 0.08}}}},
          {"balls", balls},
          {"integrator", {{"scheme", "velocity_verlet"}, {"dashpot_velocity", "half_step"}}},
          {"time", {{"dt", 2e-6}, {"duration", 0.1}}},
          {"output", {{"series_interval", 0.002}, {"dump_interval_steps", 1000}}},
          {"verify", {{"checks", {{{"type", "energy_balance"}, {"tolerance", 0.05}}}}}},
          {"compare", {{"checks", {{{"type", "energy_terms"}}}}}}};
}

}  // namespace

TEST(Ranks, OneAndTwoRanksRunTheSamePileInLammpsAndLiggghts) {
  if (harness::find_on_path("mpirun").empty()) GTEST_SKIP() << "mpirun not found (Debian's openmpi-bin)";
  const fs::path dir = fs::temp_directory_path() / "silodem_test_ranks";
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir);
  std::ofstream(dir / "ranks_pile.json") << pile().dump();
  json summary[2][2];
  const char* codes[2] = {"lammps", "liggghts"};
  for (int ranks : {1, 2}) {
    harness::CompareOptions opt;
    opt.out_root = dir / ("ranks" + std::to_string(ranks));
    opt.progress = false;
    opt.codes = {"silodem", "lammps", "liggghts"};
    opt.parallel = {ranks, "mpirun"};
    (void)harness::compare_cases({dir / "ranks_pile.json"}, opt);
    for (int c = 0; c < 2; ++c) {
      std::ifstream in(opt.out_root / "ranks_pile" / "base" / codes[c] / "summary.json");
      ASSERT_TRUE(in.good()) << codes[c] << " on " << ranks << " ranks";
      summary[c][ranks - 1] = json::parse(in);
    }
  }
  for (int c = 0; c < 2; ++c) {
    const json &one = summary[c][0], &two = summary[c][1];
    EXPECT_EQ(one["ranks"], 1) << codes[c];
    EXPECT_EQ(two["ranks"], 2) << codes[c];
    EXPECT_EQ(two["command"].get<std::string>().rfind("mpirun -np 2 ", 0), 0u) << two["command"];
    const double g0 = one["energy"]["gravitational"], g1 = two["energy"]["gravitational"];
    const double k0 = one["energy"]["kinetic"], k1 = two["energy"]["kinetic"];
    EXPECT_LT(g1 - 0.0234, 0.0) << "the pile has fallen";
    EXPECT_NEAR(g1, g0, 1e-12 * std::abs(g0)) << codes[c];
    EXPECT_NEAR(k1, k0, 1e-12 * std::abs(g0)) << codes[c];
  }
}
