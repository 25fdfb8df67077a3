#include "silodem/case/feasibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "silodem/case/case_error.hpp"
#include "silodem/case/hertz_time_step.hpp"
#include "silodem/case/json_reader.hpp"
#include "silodem/contact/pair_table.hpp"
#include "silodem/contact/stiffest_pair.hpp"
#include "silodem/integrate/stability.hpp"

namespace silodem {

double estimated_wall_balls(const WallSpec& w) {
  // Mirrors the ring and row counts of build_wall(), in doubles so that nothing overflows.
  const double s = w.spacing;
  const auto ring = [s](double radius) { return std::max(3.0, std::ceil(2.0 * kPi * radius / s)); };
  if (w.type == "drum") {  // rings along the axis × (faces + lifters), and two end plates
    const double rings = w.length > 0.0 ? std::ceil(w.length / s) + 1.0 : 1.0, R = 0.5 * w.diameter;
    const double plate = w.length > 0.0 ? 2.0 * std::pow(std::ceil(2.0 * R / s) + 1.0, 2) : 0.0;
    return rings * (ring(R) + double(w.sides) + w.lifters * (std::ceil(w.lifter_height / s) + 1.0)) + plate;
  }
  if (w.type == "tray") {  // rows across the depth × (floor + two sides), and a box's front and back
    const double rows = w.depth > 0.0 ? std::ceil(w.depth / s) + 1.0 : 1.0;
    const double along = std::ceil(w.length / s) + 1.0 + double(w.slots.size()), up = std::ceil(w.height / s) + 1.0;
    return rows * (along + 2.0 * up) + (w.depth > 0.0 ? 2.0 * along * up : 0.0);
  }
  if (w.type == "cylinder") return ring(0.5 * w.diameter) * std::max(1.0, std::ceil(w.height / s) + 1.0);
  if (w.type == "disk") {
    const double rings = std::max(1.0, std::ceil(0.5 * (w.diameter - w.hole_diameter) / s));
    return (rings + 1.0) * ring(0.5 * w.diameter);
  }
  const double slant = std::hypot(0.5 * (w.diameter - w.hole_diameter), w.height);
  return (std::max(1.0, std::ceil(slant / s)) + 1.0) * ring(0.5 * w.diameter);
}

void check_wall_geometry(const CaseConfig& cfg, const std::string& walls_path) {
  double r_small = std::numeric_limits<double>::infinity();
  for (const auto& b : cfg.balls)
    if (!b.fixed) r_small = std::min(r_small, b.radius);
  if (cfg.drops && cfg.drops->count > 0) r_small = std::min(r_small, cfg.drops->r_min);
  if (!std::isfinite(r_small)) return;
  const std::string ball = "the smallest mobile ball (diameter " + format_number(2.0 * r_small) + " m)";
  for (std::size_t i = 0; i < cfg.walls.size(); ++i) {
    const WallSpec& w = cfg.walls[i];
    const std::string path = walls_path + "[" + std::to_string(i) + "]";
    if (w.type == "tray") {
      if (w.length < 2.0 * r_small)
        throw CaseError(path + ".length", "the tray (length " + format_number(w.length) + " m) is too short to hold " + ball);
      for (const auto& slot : w.slots)
        if (slot.width < 2.0 * r_small)
          throw CaseError(path + ".slots", "the slot at x = " + format_number(slot.x) + " m (width " +
                                               format_number(slot.width) + " m) is narrower than " + ball +
                                               ": no ball can flow out");
      continue;
    }
    // A disk is a floor and may be smaller than a ball; a cylinder or hopper must contain one.
    if (w.type != "disk" && w.diameter < 2.0 * r_small)
      throw CaseError(path + ".diameter", "the " + w.type + " (diameter " + format_number(w.diameter) +
                                              " m) is too small to hold " + ball);
    if (w.hole_diameter > 0.0 && w.hole_diameter < 2.0 * r_small)
      throw CaseError(path + ".hole_diameter", "the outlet (" + format_number(w.hole_diameter) +
                                                   " m) is smaller than " + ball + ": no ball can flow out");
  }
}

double smallest_radius(const CaseConfig& cfg) {
  double r_min = std::numeric_limits<double>::infinity();
  for (const auto& b : cfg.balls) r_min = std::min(r_min, b.radius);
  if (cfg.drops) r_min = std::min(r_min, cfg.drops->r_min);
  return r_min;
}

void check_initial_travel(const CaseConfig& cfg, const std::function<std::string(std::size_t)>& path_of,
                          const std::string& release_speed_path) {
  const double allowed = cfg.guards.max_travel_ratio * smallest_radius(cfg);  // m per step
  const auto refuse = [&](const std::string& path, const std::string& what, double speed) {
    char v[32];
    std::snprintf(v, sizeof v, "%.6g", speed);  // 8000, not format_number's shortest 8e+03
    throw CaseError(path, what + " moves " + format_number(speed * cfg.dt) + " m per step at " + v +
                              " m/s (dt = " + format_number(cfg.dt) + " s), more than guards.max_travel_ratio = " +
                              format_number(cfg.guards.max_travel_ratio) + " of the smallest radius " +
                              format_number(smallest_radius(cfg)) + " m: it can pass through a ball between two steps; "
                              "a time step of at most " + format_number(allowed / speed) + " s resolves this speed");
  };
  for (std::size_t i = 0; i < cfg.balls.size(); ++i) {
    const BallSpec& b = cfg.balls[i];
    if (!b.fixed && b.velocity.norm() * cfg.dt > allowed)
      refuse(path_of(i) + ".velocity", "ball \"" + b.id + "\"", b.velocity.norm());
  }
  if (cfg.drops && cfg.drops->release && cfg.drops->release_speed * cfg.dt > allowed)
    refuse(release_speed_path, "a released drop", cfg.drops->release_speed);
}

namespace {

/// The linear law's modes per pair of kinds: normal, and with a history spring the tangential one.
std::vector<ModeLimit> linear_mode_limits(const CaseConfig& cfg) {
  // A sphere's tangential mode has the effective mass 2/7 m*: with a linear history spring
  // k_t = ρ k_n it oscillates at √(7ρ/2) ω0, with the damping ratio ρ_γ ζ √(7/(2ρ)) of a tangential
  // dashpot γ_t = ρ_γ c_n (docs/model.md §10.6), with each pair's own ρ and ρ_γ (combined, or
  // given in material_pairs). The spring is loaded by the force law, not by the integrator, so
  // its limits are the tangential ones of theory.md §7.7 (√2 for the default velocity Verlet).
  const bool history = cfg.contact.tangential == TangentialModel::LinearHistory;
  const contact::PairTable table = history ? contact::pair_table(cfg) : contact::PairTable();
  std::vector<ModeLimit> out;
  const auto mode = [&](const StiffestPair& pair, const std::string& name, const StabilityLimit& l, double omega,
                        double zeta) {
    out.push_back({l, pair.description,
                   name + format_number(omega) + " rad/s, zeta = " + format_number(zeta)});
  };
  for (const auto& pair : contact_pairs(cfg)) {
    const double w0 = pair.behaviour.omega0, zeta = pair.behaviour.zeta;
    mode(pair, "w0 = ", stable_time_step(cfg.integrator, w0, zeta), w0, zeta);
    const contact::PairParams* pp = history ? &table.at(pair.material_a, pair.material_b) : nullptr;
    if (pp && pp->shear_ratio > 0.0) {
      const double rho = pp->shear_ratio;
      const double slip = 1.0 + 1.0 / cfg.inertia_factor;  // m*/m_t (theory.md §7.7): 7/2 spheres, 3 discs
      const double w_t = std::sqrt(slip * rho) * w0, z_t = pp->shear_damping_ratio * zeta * std::sqrt(slip / rho);
      mode(pair, "tangential mode, k_t/k_n = " + format_number(rho) + ": w_t = ",
           stable_tangential_time_step(cfg.integrator, w_t, z_t), w_t, z_t);
    }
  }
  return out;
}

}  // namespace

void check_time_step(const CaseConfig& cfg, const std::string& dt_path) {
  // With damping the tightest pair need not be the stiffest one, so every pair and mode is tried.
  const std::vector<ModeLimit> modes =
      cfg.contact.normal == NormalModel::Hertz ? hertz_mode_limits(cfg) : linear_mode_limits(cfg);
  const ModeLimit* worst = nullptr;
  for (const auto& m : modes)
    if (!worst || !(m.limit.dt_max >= worst->limit.dt_max)) worst = &m;
  if (worst && !(cfg.dt <= worst->limit.dt_max)) {
    const char* scheme = cfg.integrator.scheme == Scheme::RungeKuttaMidpoint ? "runge_kutta_midpoint"
                         : cfg.integrator.scheme == Scheme::VelocityVerlet
                             ? (cfg.integrator.half_step_dashpot ? "velocity_verlet (half_step dashpot)"
                                                                 : "velocity_verlet")
                             : (cfg.integrator.max_corrector_passes == 1 ? "predictor_corrector"
                                                                         : "predictor_corrector (multiple passes)");
    throw CaseError(dt_path, "the time step " + format_number(cfg.dt) + " s is above the stability limit " +
                                 format_number(worst->limit.dt_max) + " s of " + scheme + " (" + worst->limit.rule +
                                 ") for the pair " + worst->pair + " (" + worst->detail + ")");
  }
}

}  // namespace silodem
