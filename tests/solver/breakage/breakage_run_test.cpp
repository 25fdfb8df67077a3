// Breakage in a run (docs/model.md §14) against another run and closed forms. Without gravity a
// spinning ore grain hits a fixed steel anvil, rebounds, and breaks as the contact ends: its three
// fragments fly on as one body, because their birth overlaps carry no force (notes B11), so their
// centre of mass, momentum and spacing are the unbroken grain's (a twin run without breakage) to
// 1e-12; their volumes sum to the grain's; the ledger books the break's work, which is the closed
// form ½ M ω² ((r − r_f)² + κ r_f² − κ r²) of the rigid-body field, and closes. Directly on the
// force loop: an exempt contact carries no force until it ends, reports no end, and a later touch of
// the same two fragments is a full Hertz contact whose end reports (8/15) E* √R* δ_max^(5/2).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "silodem/case/case_loader.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/run/simulation.hpp"
#include "silodem/scene/scene_builder.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using silodem::Vec3;

namespace {

constexpr double kR = 0.01, kV = 2.0, kOmega = 30.0, kEnd = 0.004;

json materials() {
  return {{"ore", {{"density", 4800}, {"youngs_modulus", 6e10}, {"poisson_ratio", 0.25}, {"restitution", 0.6}, {"friction", 0.3}}},
          {"steel", {{"density", 7800}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}, {"restitution", 0.6}, {"friction", 0.3}}}};
}

json anvil_case(bool breaking) {
  json c = {{"name", breaking ? "breakage_anvil" : "breakage_anvil_whole"},
            {"gravity", {0, 0, 0}},
            {"contact", {{"normal", "hertz"}, {"tangential", "coulomb_sliding"}}},
            {"materials", materials()},
            {"balls",
             {{{"id", "anvil"}, {"material", "steel"}, {"radius", kR}, {"position", {0, 0, 0}}, {"fixed", true}},
              {{"id", "grain"}, {"material", "ore"}, {"radius", kR}, {"position", {2.05 * kR, 0, 0}},
               {"velocity", {-kV, 0, 0}}, {"angular_velocity", {0, kOmega, 0}}}}},
            {"time", {{"dt", 2e-7}, {"duration", kEnd}}}};
  if (breaking)
    c["breakage"] = {{"materials", {"ore"}}, {"minimum_energy", 0.0}, {"strength", 1e9}, {"fragments", {{"min", 3}, {"max", 3}}}};
  return c;
}

json run(const json& c) {
  const fs::path out = fs::temp_directory_path() / ("silodem_" + c["name"].get<std::string>());
  fs::remove_all(out);  // the test's own scratch
  json s = silodem::run_case(silodem::load_case(c), {out, false, false});
  s["state"] = json::parse(std::ifstream(out / "state.json"));
  if (fs::exists(out / "breakage.csv")) {  // the first break's time
    std::ifstream csv(out / "breakage.csv");
    std::string line;
    std::getline(csv, line);
    if (std::getline(csv, line) && !line.empty()) s["first_break_time"] = std::stod(line.substr(0, line.find(',')));
  }
  fs::remove_all(out);
  return s;
}

Vec3 vec(const json& a) { return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()}; }

}  // namespace

TEST(BreakageRun, FragmentsOfAGrainBrokenInFlightMoveOnAsTheWholeGrainAndTheLedgerBooksTheBreak) {
  const json whole = run(anvil_case(false)), broken = run(anvil_case(true));
  ASSERT_EQ(broken["breakage"]["breaks"].get<int>(), 1);
  ASSERT_EQ(broken["breakage"]["fragments"].get<int>(), 3);
  ASSERT_TRUE(broken.contains("first_break_time"));
  const double flight = kEnd - broken["first_break_time"].get<double>();
  const json* grain = nullptr;
  for (const json& b : whole["state"]["balls"])
    if (b["id"] == "grain") grain = &b;
  ASSERT_NE(grain, nullptr);
  const Vec3 x_whole = vec((*grain)["position"]), v_whole = vec((*grain)["velocity"]), w_whole = vec((*grain)["angular_velocity"]);
  ASSERT_GT(v_whole.x(), 0.3 * kV) << "the whole grain rebounds";
  std::vector<Vec3> xs;
  Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero();
  double volume = 0.0, r_f = 0.0;
  for (const json& b : broken["state"]["balls"]) {
    if (b["id"] == "anvil") continue;
    xs.push_back(vec(b["position"]));
    centre += vec(b["position"]) / 3.0;
    momentum += vec(b["velocity"]) / 3.0;
    r_f = b["radius"].get<double>();
    volume += std::pow(r_f, 3);
    EXPECT_NEAR((vec(b["angular_velocity"]) - w_whole).norm(), 0.0, 1e-12 * kOmega);
  }
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_NEAR(volume, kR * kR * kR, 1e-12 * kR * kR * kR);
  EXPECT_NEAR((centre - x_whole).norm(), 0.0, 1e-12);
  EXPECT_NEAR((momentum - v_whole).norm(), 0.0, 1e-12 * kV);
  // No force between birth overlaps: each fragment flies straight at its rigid-body velocity, so two
  // of them, √3 (r − r_f) apart at birth, part at ω |Δx| across their line: d = d0 √(1 + (ω τ)²).
  const double d0 = std::sqrt(3.0) * (kR - r_f), d = d0 * std::sqrt(1.0 + w_whole.squaredNorm() * flight * flight);
  for (std::size_t a = 0; a < 3; ++a) EXPECT_NEAR((xs[a] - xs[(a + 1) % 3]).norm(), d, 1e-12);
  // The break's work: the fragments' spins and their rigid-body motion about the centre, less the grain's spin.
  const double m = 4800.0 * 4.0 / 3.0 * M_PI * kR * kR * kR, w2 = w_whole.squaredNorm();
  const double work = 0.5 * m * w2 * (std::pow(kR - r_f, 2) + 0.4 * r_f * r_f - 0.4 * kR * kR);
  EXPECT_NEAR(broken["breakage"]["work"].get<double>(), work, 1e-9 * std::abs(work));
  EXPECT_LT(std::abs(broken["energy"]["relative_drift"].get<double>()), 1e-3);
  EXPECT_NEAR(broken["energy"]["relative_drift"].get<double>(), whole["energy"]["relative_drift"].get<double>(), 1e-9)
      << "booked, the break adds nothing to the ledger's residual";
}

// breakage.from_time: the same impact, its contact ending before from_time, breaks nothing; and
// from_time just before that end changes nothing from the default.
TEST(BreakageRun, AContactEndingBeforeFromTimeCountsNothing) {
  json late = anvil_case(true), early = anvil_case(true);
  const json broken = run(anvil_case(true));
  const double ends = broken["first_break_time"].get<double>();
  late["name"] = "breakage_anvil_late", early["name"] = "breakage_anvil_early";
  late["breakage"]["from_time"] = ends + 1e-5;
  early["breakage"]["from_time"] = ends - 1e-5;
  EXPECT_EQ(run(late)["breakage"]["breaks"].get<int>(), 0);
  const json counted = run(early);
  EXPECT_EQ(counted["breakage"]["breaks"].get<int>(), 1);
  EXPECT_EQ(counted["first_break_time"].get<double>(), ends);
}

TEST(BreakageRun, ABirthOverlapCarriesNoForceUntilItEndsThenTheFragmentsMeetAsHertzContacts) {
  json c = anvil_case(true);
  c["balls"] = {{{"id", "a"}, {"material", "ore"}, {"radius", kR}, {"position", {0, 0, 0}}},
                {{"id", "b"}, {"material", "ore"}, {"radius", kR}, {"position", {1.6 * kR, 0, 0}}}};
  const silodem::CaseConfig cfg = silodem::load_case(c);
  silodem::Scene scene = silodem::build_scene(cfg);
  silodem::Particles& p = scene.particles;
  silodem::NeighbourList list(0.2 * kR, 0.0);
  const auto field = silodem::make_force_field(cfg);
  const auto evaluate = [&] {
    list.update(p);
    field->compute(p, list);
    field->commit();
  };
  field->set_newborn({p.tag[0], p.tag[1]});
  evaluate();  // born overlapping by 0.4 r
  EXPECT_EQ(p.f[0].norm(), 0.0);
  p.x[1].x() = 1.8 * kR;
  evaluate();  // still overlapping: still exempt
  EXPECT_EQ(p.f[0].norm(), 0.0);
  p.x[1].x() = 2.1 * kR;
  evaluate();  // apart: the exempt contact ends without a report
  EXPECT_TRUE(field->take_ended_contacts().empty());
  const double delta = 1e-5;
  p.x[1].x() = 2.0 * kR - delta;
  evaluate();  // a new contact: Hertz, (4/3) E* sqrt(R*) δ^(3/2) at rest
  const double e_star = 1.0 / (2.0 * (1.0 - 0.25 * 0.25) / 6e10), r_star = 0.5 * kR;
  EXPECT_NEAR(-p.f[0].x(), 4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(delta, 1.5), 1e-12 * p.f[0].norm());
  p.x[1].x() = 2.0 * kR + 1e-6;
  evaluate();
  const auto ended = field->take_ended_contacts();
  ASSERT_EQ(ended.size(), 1u);
  EXPECT_NEAR(ended[0].energy, 8.0 / 15.0 * e_star * std::sqrt(r_star) * std::pow(delta, 2.5), 1e-12 * ended[0].energy);
}

TEST(BreakageKeys, TheLoaderRefusesWhatBreakageCannotRunNamingTheKey) {
  const auto refusal = [](json c) -> std::string {
    try {
      silodem::load_case(c);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  json linear = anvil_case(true);
  linear["contact"] = {{"normal", "linear"}, {"tangential", "coulomb_sliding"}};
  linear["materials"] = {{"ore", {{"density", 4800}, {"stiffness", 1e6}, {"restitution", 0.6}, {"friction", 0.3}, {"reference_radius", kR}}},
                         {"steel", {{"density", 7800}, {"stiffness", 1e6}, {"restitution", 0.6}, {"friction", 0.3}, {"reference_radius", kR}}}};
  EXPECT_NE(refusal(linear).find("breakage is built on Hertz contacts"), std::string::npos) << refusal(linear);
  json unknown = anvil_case(true);
  unknown["breakage"]["materials"] = {"granite"};
  EXPECT_NE(refusal(unknown).find("$.breakage.materials[0]: no material named \"granite\""), std::string::npos) << refusal(unknown);
  json counts = anvil_case(true);
  counts["breakage"]["fragments"] = {{"min", 5}, {"max", 3}};
  EXPECT_NE(refusal(counts).find("$.breakage.fragments.max"), std::string::npos) << refusal(counts);
  json weak = anvil_case(true);
  weak["breakage"]["strength"] = 0.0;
  EXPECT_NE(refusal(weak).find("$.breakage.strength: must be > 0"), std::string::npos) << refusal(weak);
}
