#pragma once
// One ball on a floor, as the friction tests build it: the case, its run, and the probe's values.
// A "floor" is one fixed ball of radius 1000 m: over the few centimetres a ball travels here its
// surface departs from a plane by under 10⁻⁶ m and tilts by under 10⁻⁴ rad.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace silodem_test {

namespace fs = std::filesystem;
using nlohmann::json;

inline constexpr double kFloorRadius = 1000.0;

inline json run(const json& c) {
  const silodem::CaseConfig cfg = silodem::load_case(c);
  const fs::path out = fs::temp_directory_path() / ("silodem_friction_" + cfg.name);
  fs::remove_all(out);  // the test's own scratch
  json s = silodem::run_case(cfg, {out, false, false});
  std::ifstream events(out / "probes" / "pair.csv");
  if (events) {
    std::string header, row;
    std::getline(events, header);
    if (std::getline(events, row)) s["first_event"] = row;
  }
  fs::remove_all(out);
  return s;
}

inline const json& probe(const json& s, const std::string& name) { return s["probes"][name]; }

inline Eigen::Vector3d vec(const json& a) { return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()}; }

/// The pair probe's first event as numbers: duration, restitution, max_overlap.
struct Event {
  double duration, restitution, max_overlap;
};
inline Event first_event(const json& s) {
  std::stringstream row(s.at("first_event").get<std::string>());
  std::vector<double> cells;
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell.empty() ? NAN : std::stod(cell));
  return {cells.at(3), cells.at(6), cells.at(7)};
}

/// A ball of radius r on the floor, resting at its static overlap, thrown at u0 along x with spin w0.
inline json on_floor(const std::string& name, const json& contact, const json& grain, double r, double u0, double w0_y,
              double duration) {
  const double k_pair = 0.5 * grain["stiffness"].get<double>();  // the floor has the same per-ball k
  const double m = grain["density"].get<double>() * 4.0 / 3.0 * M_PI * r * r * r;
  const double static_overlap = m * 9.81 / k_pair;
  const json& floor = grain;  // the same constants: the pair's k is half the per-ball k (11)
  json ball = {{"id", "ball"}, {"material", "grain"}, {"radius", r},
               {"position", {0.0, 0.0, kFloorRadius + r - static_overlap}}, {"velocity", {u0, 0.0, 0.0}}};
  if (w0_y != 0.0) ball["angular_velocity"] = {0.0, w0_y, 0.0};
  return {{"name", name},
          {"contact", contact},
          {"materials", {{"grain", grain}, {"floor", floor}}},
          {"balls", {ball, {{"id", "floor"}, {"material", "floor"}, {"radius", kFloorRadius}, {"position", {0, 0, 0}}, {"fixed", true}}}},
          {"time", {{"dt", 1e-5}, {"duration", duration}}},
          {"output", {{"probes", {{{"type", "ball"}, {"name", "ball"}, {"balls", {"ball"}}}}}}}};
}

/// A ball at rest at its static overlap on the floor under gravity tilted by θ about y: the floor
/// is then an incline of angle θ (down-slope along +x).
inline json on_incline(const std::string& name, const json& contact, const json& grain, double r, double theta_deg,
                double duration) {
  const double th = theta_deg * M_PI / 180.0, g = 9.81;
  json c = on_floor(name, contact, grain, r, 0.0, 0.0, duration);
  const double m = grain["density"].get<double>() * 4.0 / 3.0 * M_PI * r * r * r;
  const double k_pair = 0.5 * grain["stiffness"].get<double>();
  c["gravity"] = {g * std::sin(th), 0.0, -g * std::cos(th)};
  c["balls"][0]["position"] = {0.0, 0.0, kFloorRadius + r - m * g * std::cos(th) / k_pair};
  c["balls"][0].erase("velocity");
  return c;
}


}  // namespace silodem_test
