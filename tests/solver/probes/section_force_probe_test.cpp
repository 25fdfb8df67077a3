// The section force probe against statics: a stack of grains at rest on a fixed floor ball carries,
// across any plane between two of them, the weight of the grains above — whatever the plane cuts,
// the force on the body above from the body below is that weight at rest. A plane above every ball
// carries nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kG = 9.81, kDensity = 2500.0;
const double kRadii[3] = {0.005, 0.004, 0.006};  // bottom to top

double mass(double r) { return kDensity * 4.0 / 3.0 * M_PI * r * r * r; }

/// Three grains stacked on a fixed floor ball, settled by their damping; planes between each pair.
json stack_case() {
  json balls = json::array({{{"id", "floor"}, {"material", "grain"}, {"radius", 0.01}, {"position", {0, 0, 0}}, {"fixed", true}}});
  double z = 0.01;
  for (int k = 0; k < 3; ++k) {
    z += kRadii[k];
    balls.push_back({{"id", "g" + std::to_string(k)}, {"material", "grain"}, {"radius", kRadii[k]}, {"position", {0, 0, z}}});
    z += kRadii[k];
  }
  json probes = json::array();
  // Between the floor and g0, g0 and g1, g1 and g2, and above everything.
  for (const double plane : {0.0101, 0.0201, 0.0281, 0.05})
    probes.push_back({{"type", "section_force"}, {"name", "z" + std::to_string(int(plane * 1e4))}, {"z", plane}, {"interval", 0.01}});
  return {{"name", "stack"},
          {"gravity", {0, 0, -kG}},
          {"materials", {{"grain", {{"density", kDensity}, {"stiffness", 2e5}, {"restitution", 0.3}, {"reference_radius", 0.005}}}}},
          {"balls", balls},
          {"integrator", {{"scheme", "velocity_verlet"}}},
          {"time", {{"dt", 2e-6}, {"duration", 0.3}}},
          {"output", {{"probes", probes}}}};
}

}  // namespace

TEST(SectionForceProbe, AStackAtRestCarriesTheWeightAboveEachPlane) {
  const fs::path out = fs::temp_directory_path() / "silodem_section_force_stack";
  fs::remove_all(out);  // the test's own scratch
  const json s = silodem::run_case(silodem::load_case(stack_case()), {out, false, false});
  const double m0 = mass(kRadii[0]), m1 = mass(kRadii[1]), m2 = mass(kRadii[2]);
  // Damping ratio of e = 0.3 leaves, after 0.3 s, no motion at the 1e-9 level (the contact period
  // is about 0.1 ms): the force across is the weight above to that order.
  const std::pair<std::string, double> expected[] = {
      {"z101", (m0 + m1 + m2) * kG}, {"z201", (m1 + m2) * kG}, {"z281", m2 * kG}, {"z500", 0.0}};
  for (const auto& [name, weight] : expected) {
    const auto& f = s["probes"][name]["force_final"];
    EXPECT_NEAR(f[2].get<double>(), weight, 1e-9 * (m0 + m1 + m2) * kG) << name;
    EXPECT_EQ(f[0].get<double>(), 0.0) << name;  // a vertical stack: no horizontal force at all
    EXPECT_EQ(f[1].get<double>(), 0.0) << name;
    EXPECT_EQ(s["probes"][name]["rows"].get<std::size_t>(), 31u) << name;  // t = 0, 0.01, ..., 0.3
  }
}
