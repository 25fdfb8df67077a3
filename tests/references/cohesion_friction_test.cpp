// The paper's cohesion zone (9)–(10) with friction and rolling resistance on (docs/model.md §10):
// in the zone the pair is apart, so only the tensile spring acts. Head-on pairs slip nowhere, so
// the frictional law must give the frictionless law's separations — which cases/cohesion_cutoff.json
// judges against the closed form of docs/theory.md §2a — and no torque.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "friction_scenes.hpp"

using namespace silodem_test;

namespace {

json cutoff_case() {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "cohesion_cutoff.json");
  json c = json::parse(in);
  c.erase("verify");
  c.erase("compare");
  c["time"]["duration"] = 1e-4;
  c["output"]["series_interval"] = 1e-4;
  json probes = json::array();
  for (const char* id : {"equal_95_a", "equal_105_a", "unequal_95_a", "unequal_105_a"})
    probes.push_back({{"type", "ball"}, {"name", id}, {"balls", {id}}});
  c["output"]["probes"] = probes;
  return c;
}

}  // namespace

TEST(CohesionWithFriction, HeadOnPairsSeparateExactlyAsWithoutFrictionAndNeverTurn) {
  json plain = cutoff_case();
  plain["name"] = "cohesion_plain";
  json rough = cutoff_case();
  rough["name"] = "cohesion_rough";
  rough["contact"]["tangential"] = "linear_history";
  rough["contact"]["rolling"] = "epsd";
  rough["materials"]["grain"]["friction"] = 0.5;
  rough["materials"]["grain"]["rolling_friction"] = 0.1;
  const json a = run(plain), b = run(rough);
  for (const char* id : {"equal_95_a", "equal_105_a", "unequal_95_a", "unequal_105_a"}) {
    const Eigen::Vector3d va = vec(probe(a, id)["final_velocity"]), vb = vec(probe(b, id)["final_velocity"]);
    const Eigen::Vector3d xa = vec(probe(a, id)["final_position"]), xb = vec(probe(b, id)["final_position"]);
    EXPECT_LE((va - vb).norm(), 1e-12 * va.norm() + 1e-15) << id;
    EXPECT_LE((xa - xb).norm(), 1e-12 * xa.norm()) << id;
    EXPECT_EQ(vec(probe(b, id)["final_angular_velocity"]).norm(), 0.0) << id;
  }
  // The cohesion springs are booked as in the frictionless ledger.
  EXPECT_NEAR(b["energy"]["elastic"].get<double>(), a["energy"]["elastic"].get<double>(),
              1e-12 * std::abs(a["energy"]["kinetic"].get<double>()));
  EXPECT_NEAR(b["energy"]["balance"].get<double>(), a["energy"]["balance"].get<double>(),
              1e-12 * std::abs(a["energy"]["kinetic"].get<double>()));
}
