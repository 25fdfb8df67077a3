#include "harness/mill_checks.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>  // cross products
#include <stdexcept>

namespace harness {

using nlohmann::json;
using silodem::Vec3;

namespace {

Vec3 vec(const json& a) { return {a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()}; }

const silodem::WallSpec& wall_named(const silodem::CaseConfig& cfg, const std::string& name) {
  for (const auto& w : cfg.walls)
    if (w.name == name) return w;
  throw std::runtime_error("no wall " + name);
}

const silodem::ProbeSpec& probe_named(const silodem::CaseConfig& cfg, const std::string& name) {
  for (const auto& p : cfg.probes)
    if (p.name == name) return p;
  throw std::runtime_error("no probe " + name);
}

/// Mellmann (2001), Table 1: the forms of transverse motion by Froude number.
std::string mellmann_regime(double fr) {
  if (fr >= 1.0) return "centrifuging (Fr >= 1)";
  if (fr >= 0.1) return "cataracting (0.1 < Fr < 1)";
  if (fr >= 1e-3) return "cascading (1e-3 < Fr < 0.1; rolling below 1e-2)";
  if (fr >= 1e-4) return "rolling (1e-4 < Fr < 1e-2)";
  return "slipping or slumping (Fr < 1e-4)";
}

}  // namespace

std::vector<CheckRow> torque_identity(const json& spec, const RunContext& ctx) {
  const std::string wall_probe = spec.at("wall_probe"), charge_probe = spec.at("charge_probe");
  const json& load = ctx.result.probe_digest(wall_probe);
  const json& charge = ctx.result.probe_digest(charge_probe);
  const silodem::WallSpec& wall = wall_named(ctx.cfg, probe_named(ctx.cfg, wall_probe).wall);
  const Vec3 axis = wall.motion->axis.normalized(), c = vec(charge.at("about"));
  const json& win = charge.at("window");
  const double t0 = win.at("start").at("t").get<double>(), t1 = charge.at("final").at("t").get<double>(), span = t1 - t0;
  const double mass = win.at("mean_mass").get<double>();
  const Vec3 l0 = vec(win.at("start").at("angular_momentum")), l1 = vec(charge.at("final").at("angular_momentum"));
  const double gravity_term = axis.dot(mass * (vec(win.at("mean_centre_of_mass")) - c).cross(ctx.cfg.gravity));
  const double expected = gravity_term - axis.dot(l1 - l0) / span;
  const double measured = axis.dot(vec(load.at("torque_mean")));
  // Means over N samples against the integrals over τ = (N − 1)Δt: each differs by at most its
  // largest sample over N − 1 (the end terms), the drum's torque and gravity's M g R alike.
  const double n = load.at("samples").get<double>();
  const double lever = 0.5 * wall.diameter;
  const double bound = 2.0 * (load.at("torque_abs_max").get<double>() + mass * ctx.cfg.gravity.norm() * lever) / (n - 1.0);
  CheckRow t = match_row(ctx, "drum_torque", wall_probe, expected, measured, bound / std::abs(expected),
                         "scheme bound: the sampled means' end terms, 2 (max|T| + M g R)/(N - 1)");
  t.note = "M g x_c term " + std::to_string(gravity_term) + " N m, -dL/tau " + std::to_string(-axis.dot(l1 - l0) / span) +
           " N m over " + std::to_string(span) + " s";
  const double omega = wall.motion->angular_speed;
  const double power = load.at("power_mean").get<double>();
  CheckRow p = match_row(ctx, "drum_power", wall_probe, -omega * measured, power, 1e-9,
                         "exact: a turning wall's ball velocities are the rigid field, so P = -Omega T to round-off");
  return {t, p};
}

std::vector<CheckRow> mill_regime(const json& spec, const RunContext& ctx) {
  const std::string charge_probe = spec.at("charge_probe");
  const json& charge = ctx.result.probe_digest(charge_probe);
  const silodem::WallSpec& wall = wall_named(ctx.cfg, spec.at("wall").get<std::string>());
  const double g = ctx.cfg.gravity.norm(), radius = 0.5 * wall.diameter, omega = std::abs(wall.motion->angular_speed);
  const double fr = omega * omega * radius / g;
  const Vec3 axis = wall.motion->axis.normalized(), down = ctx.cfg.gravity.normalized();
  const Vec3 offset = vec(charge.at("window").at("mean_centre_of_mass")) - vec(charge.at("about"));
  const Vec3 across = axis.cross(down);  // horizontal, across the axis
  const double angle = std::atan2(offset.dot(across), offset.dot(down)) * 180.0 / M_PI;
  const std::string why = "a regime figure: no closed form for a frictional charge";
  std::vector<CheckRow> out;
  CheckRow f = report_row(ctx, "froude_number", charge_probe, fr, "the run's set speed: Omega^2 R / g");
  f.note = "Mellmann (2001): " + mellmann_regime(fr);
  out.push_back(f);
  out.push_back(report_row(ctx, "speed_over_critical", charge_probe, std::sqrt(fr), "the run's set speed: Omega / sqrt(g/R)"));
  out.push_back(report_row(ctx, "dynamic_angle_deg", charge_probe, angle, why));
  const double ke = charge.at("final").at("kinetic").get<double>() / charge.at("final").at("mass").get<double>();
  out.push_back(report_row(ctx, "kinetic_energy_per_mass", charge_probe, ke, why + " (J/kg at the end)"));
  return out;
}

std::vector<CheckRow> charge_volume(const json& spec, const RunContext& ctx) {
  const std::string charge_probe = spec.at("charge_probe");
  const json& charge = ctx.result.probe_digest(charge_probe);
  const double v0 = charge.at("first").at("volume").get<double>(), v1 = charge.at("final").at("volume").get<double>();
  std::vector<CheckRow> out{match_row(ctx, "charge_volume", charge_probe, v0, v1, 1e-12,
                                      "exact: fragments keep their parent's volume, sum r_f^3 = r^3 (model.md §14)")};
  if (ctx.result.summary.contains("breakage")) {
    const json& b = ctx.result.summary.at("breakage");
    CheckRow r = report_row(ctx, "breaks", charge_probe, b.at("breaks").get<double>(), "a grinding result: the model's toughness is random");
    r.note = std::to_string(b.at("fragments").get<long>()) + " fragments; " +
             std::to_string(charge.at("first").at("balls").get<long>()) + " balls at the start, " +
             std::to_string(charge.at("final").at("balls").get<long>()) + " at the end";
    out.push_back(r);
  }
  return out;
}

void validate_mill_check(const std::string& type, const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  const auto probe = [&](const std::string& key, const std::string& kind) -> const silodem::ProbeSpec& {
    const std::string name = r.string(key);
    for (const auto& p : cfg.probes)
      if (p.name == name && p.type == kind) return p;
    r.fail(key, "no " + kind + " probe named \"" + name + "\"");
    throw std::logic_error("unreachable");
  };
  const auto turning = [&](const std::string& key, const std::string& wall) {
    for (const auto& w : cfg.walls)
      if (w.name == wall && w.motion && w.motion->angular_speed != 0.0) return;
    r.fail(key, "wall \"" + wall + "\" does not turn (a motion law with an angular_speed)");
  };
  const silodem::ProbeSpec& charge = probe("charge_probe", "charge");
  if (type == "torque_identity") {
    const silodem::ProbeSpec& load = probe("wall_probe", "wall_load");
    turning("wall_probe", load.wall);
    if (load.from_time != charge.from_time || load.to_time != 0.0)
      r.fail("wall_probe", "its window must be the charge probe's (the same from_time, no to_time)");
    if (!(charge.from_time > 0.0)) r.fail("charge_probe", "needs a from_time (the window of the means)");
    if (cfg.breakage) r.fail("type", "breakage changes the charge's angular momentum at each break; check a case without it");
  } else if (type == "mill_regime") {
    turning("wall", r.string("wall"));
    if (!(charge.from_time > 0.0)) r.fail("charge_probe", "needs a from_time (the window of the means)");
  }
}

}  // namespace harness
