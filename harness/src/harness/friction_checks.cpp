#include "harness/friction_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Geometry>  // cross products

#include "harness/tolerance_source.hpp"
#include "references/friction.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/contact/pair_table.hpp"

namespace harness {

using nlohmann::json;
using silodem::CaseConfig;
using silodem::Vec3;

namespace {

/// The ball a ball probe watches.
const silodem::BallSpec& probed_ball(const RunContext& ctx, const std::string& probe) {
  for (const auto& p : ctx.cfg.probes)
    if (p.name == probe) return ball(ctx.cfg, p.balls.at(0));
  throw std::runtime_error("no probe " + probe);
}

/// The friction and rolling constants of two materials as the solver combines them
/// (contact/pair_table.hpp): the case's input, not a result.
silodem::contact::PairParams pair_of(const CaseConfig& cfg, const std::string& a, const std::string& b) {
  const auto table = silodem::contact::pair_table(cfg);
  std::int32_t ia = 0, ib = 0, k = 0;
  for (const auto& [name, m] : cfg.materials) {
    if (name == a) ia = k;
    if (name == b) ib = k;
    ++k;
  }
  return table.at(ia, ib);
}
double friction_of(const CaseConfig& cfg, const std::string& a, const std::string& b) { return pair_of(cfg, a, b).friction; }

/// The restitution the case gives a material (its input, as the loader read it).
double stated_restitution(const CaseConfig& cfg, const std::string& material) {
  return cfg.source.at("materials").at(material).at("restitution").get<double>();
}

/// 1/E* of two Hertz materials, 1/E* = Σ (1 − ν²)/E (Johnson 1985).
double effective_modulus(const CaseConfig& cfg, const std::string& a, const std::string& b) {
  const auto& ma = cfg.materials.at(a);
  const auto& mb = cfg.materials.at(b);
  return 1.0 / ((1.0 - ma.poisson_ratio * ma.poisson_ratio) / ma.youngs_modulus +
                (1.0 - mb.poisson_ratio * mb.poisson_ratio) / mb.youngs_modulus);
}

Vec3 vec(const json& a) { return {a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()}; }

struct Tol {
  double value;
  std::string source;
};
Tol tol(const json& spec) {
  const double t = spec.at("tolerance").get<double>();
  return {t, tolerance_source(spec, "tolerance", t)};
}

}  // namespace

std::vector<CheckRow> hertz_impact(const json& spec, const RunContext& ctx) {
  const std::string probe = spec.at("pair_probe");
  const silodem::ProbeSpec* ps = nullptr;
  for (const auto& p : ctx.cfg.probes)
    if (p.name == probe) ps = &p;
  const auto& a = ball(ctx.cfg, ps->balls[0]);
  const auto& b = ball(ctx.cfg, ps->balls[1]);
  const double ma = mass(ctx.cfg, a), mb = mass(ctx.cfg, b);
  const double m = b.fixed ? ma : ma * mb / (ma + mb), r = a.radius * b.radius / (a.radius + b.radius);
  const Vec3 n = (a.position - b.position).normalized();
  const double speed = -(a.velocity - b.velocity).dot(n);
  const auto th = references::hertz_impact(m, r, effective_modulus(ctx.cfg, a.material, b.material), speed);
  const Tol t = tol(spec);
  const CsvTable ev = ctx.result.probe(probe);
  const bool ended = ev.size() > 0 && ev.number(0, "ended") == 1.0;
  std::vector<CheckRow> out;
  out.push_back(match_row(ctx, "hertz_max_overlap", probe, th.max_overlap, ended ? ev.number(0, "max_overlap") : NAN, t.value, t.source));
  out.push_back(match_row(ctx, "hertz_duration", probe, th.duration, ended ? ev.number(0, "duration") : NAN, t.value, t.source));
  // Not measured apart: the probe records the overlap, and the force follows from it by Hertz's law.
  out.push_back(report_row(ctx, "hertz_max_force", probe,
                           ended ? th.max_force * std::pow(ev.number(0, "max_overlap") / th.max_overlap, 1.5) : NAN,
                           "derived from the measured largest overlap by F = 4/3 E* sqrt(R*) delta^{3/2}, not measured apart "
                           "(the overlap row judges it)",
                           th.max_force));
  const double e = stated_restitution(ctx.cfg, a.material);
  out.push_back(match_row(ctx, "normal_restitution", probe, e, ended ? ev.number(0, "restitution") : NAN, t.value, t.source));
  if (!ended) for (auto& row : out) row.note = "no completed contact";
  return out;
}

std::vector<CheckRow> oblique_impact(const json& spec, const RunContext& ctx) {
  if (ctx.cfg.inertia_factor != 0.4)
    throw std::runtime_error("this check's closed form is for solid spheres (I = 2/5 m r^2); the case's grains are discs");
  const std::string probe = spec.at("ball_probe");
  const auto& grain = probed_ball(ctx, probe);
  const auto& plane = ball(ctx.cfg, spec.at("plane").get<std::string>());
  const Vec3 n = (grain.position - plane.position).normalized();
  const double vn = -grain.velocity.dot(n);
  const Vec3 vt = grain.velocity + vn * n;
  const double speed = grain.velocity.norm(), theta = std::atan2(vt.norm(), vn);
  const double mu = friction_of(ctx.cfg, grain.material, plane.material), e = stated_restitution(ctx.cfg, grain.material);
  const auto th = references::oblique_gross_sliding(mu, e, theta, speed, grain.radius);
  const json& res = ctx.result.summary.at("probes").at(probe);
  const Vec3 v = vec(res.at("final_velocity")), w = vec(res.at("final_angular_velocity"));
  const Vec3 t_hat = vt.normalized(), axis = n.cross(t_hat);  // forward roll spins about n × t̂
  const double vt_out = v.dot(t_hat), vn_out = v.dot(n), spin = w.dot(axis);
  const double rebound = std::atan((vt_out - grain.radius * spin) / vn_out);
  const Tol t = tol(spec);
  const std::string subject = probe + " theta=" + std::to_string(int(std::round(theta * 180.0 / std::numbers::pi)));
  std::vector<CheckRow> out;
  out.push_back(match_row(ctx, "normal_restitution", subject, e, vn_out / vn, t.value, t.source));
  if (!th.applies) {
    const std::string why = "incidence below arctan(3.5 mu (1+e)): the contact sticks in part, no closed form "
                            "(Chung & Ooi's curves are not digitised here)";
    out.push_back(report_row(ctx, "tangential_restitution", subject, vt_out / vt.norm(), why));
    out.push_back(report_row(ctx, "rebound_spin", subject, spin, why));
    out.push_back(report_row(ctx, "rebound_angle", subject, rebound, why));
    return out;
  }
  out.push_back(match_row(ctx, "tangential_restitution", subject, th.tangential_restitution, vt_out / vt.norm(), t.value, t.source));
  out.push_back(match_row(ctx, "rebound_spin", subject, th.spin, spin, t.value, t.source));
  // The spin's error enters the contact point's tangential velocity v_t' − rω' (theory.md §10.3),
  // a small difference near the sliding limit: relative to it, the spin's error is amplified by
  // rω'/(v_t' − rω') = (5/2)μ(1+e)cosθ / (sinθ − 3.5μ(1+e)cosθ).
  const double amplify = std::max(1.0, 2.5 * mu * (1 + e) * std::cos(theta) /
                                           (std::sin(theta) - 3.5 * mu * (1 + e) * std::cos(theta)));
  out.push_back(match_row(ctx, "rebound_angle", subject, th.rebound_angle, rebound, amplify * t.value,
                          t.source.empty() ? "" : t.source + "; times " + std::to_string(amplify) +
                                                      " = r w'/(v_t' - r w') for the angle of the contact point's velocity"));
  return out;
}

std::vector<CheckRow> slip_to_roll(const json& spec, const RunContext& ctx) {
  const std::string probe = spec.at("ball_probe");
  const auto& grain = probed_ball(ctx, probe);
  const auto& floor = ball(ctx.cfg, spec.at("floor").get<std::string>());
  const double mu = friction_of(ctx.cfg, grain.material, floor.material), g = ctx.cfg.gravity.norm();
  // A floor set moving at the start (move_wall at t = 0): the same motion in the floor's frame.
  Vec3 floor_v = Vec3::Zero();
  for (const auto& ev : ctx.cfg.events)
    if (ev.type == "move_wall" && ev.time == 0.0 && ev.names(floor.id)) floor_v = ev.velocity;
  const Vec3 relative = grain.velocity - floor_v;
  const double u0 = relative.norm(), time = ctx.cfg.duration;
  const auto th = references::slip_to_roll(u0, mu, g, grain.radius, ctx.cfg.inertia_factor);
  const json& res = ctx.result.summary.at("probes").at(probe);
  const Vec3 w = vec(res.at("final_angular_velocity"));
  const Vec3 along = relative.normalized(), axis = Vec3(0, 0, 1).cross(along);
  const Vec3 v = vec(res.at("final_velocity")) - floor_v;  // in the floor's frame
  const Tol t = tol(spec);
  const std::string phase = time < th.slip_time ? "sliding" : "rolling";
  std::vector<CheckRow> out;
  out.push_back(match_row(ctx, phase + "_speed", probe, th.speed(time), v.dot(along), t.value, t.source));
  out.push_back(match_row(ctx, phase + "_spin", probe, th.spin(time), w.dot(axis), t.value, t.source));
  for (auto& row : out) row.note = "mu=" + std::to_string(mu) + ", t_s=" + std::to_string(th.slip_time) + " s";
  return out;
}

std::vector<CheckRow> rolling_resistance(const json& spec, const RunContext& ctx) {
  if (ctx.cfg.inertia_factor != 0.4)
    throw std::runtime_error("this check's closed form is for solid spheres (I = 2/5 m r^2); the case's grains are discs");
  const std::string probe = spec.at("ball_probe");
  const auto& grain = probed_ball(ctx, probe);
  const auto& floor = ball(ctx.cfg, spec.at("floor").get<std::string>());
  const auto pp = pair_of(ctx.cfg, grain.material, floor.material);
  const Vec3 n = (grain.position - floor.position).normalized(), g = ctx.cfg.gravity;
  const Vec3 g_plane = g - g.dot(n) * n;
  // Along the throw, or down the slope from rest.
  const Vec3 along = grain.velocity.norm() > 0.0 ? Vec3(grain.velocity.normalized()) : Vec3(g_plane.normalized());
  const double r = grain.radius, r_star = r * floor.radius / (r + floor.radius), time = ctx.cfg.duration;
  const auto th = references::resisted_rolling(grain.velocity.dot(along), g.dot(along), -g.dot(n), pp.rolling_friction, r_star, r);
  const json& res = ctx.result.summary.at("probes").at(probe);
  const Vec3 v = vec(res.at("final_velocity")), w = vec(res.at("final_angular_velocity"));
  const Vec3 axis = n.cross(along);  // a forward roll spins about n × t̂
  const Tol t = tol(spec);
  const auto& mg = ctx.cfg.materials.at(grain.material);
  const auto& mf = ctx.cfg.materials.at(floor.material);
  const double k_n = silodem::contact::series(mg.k, mf.k), k_t = pp.shear_ratio * k_n, m = mass(ctx.cfg, grain);
  const double k_r = 2.25 * k_n * pp.rolling_friction * pp.rolling_friction * r_star * r_star;  // Ai et al. (2011)
  const bool spring = ctx.cfg.contact.rolling == silodem::RollingModel::Spring;
  std::vector<CheckRow> out;
  const auto report_both = [&](const std::string& why) {
    out.push_back(report_row(ctx, "rolling_speed", probe, v.dot(along), why));
    out.push_back(report_row(ctx, "rolling_spin", probe, w.dot(axis), why));
    return out;
  };
  // The closed forms start rolling without slip (or at rest): the contact point at rest, ω₀ = v₀/r.
  if ((grain.angular_velocity * r - th.v0 * axis).norm() > 1e-9 * th.v0)
    return report_both("the ball does not start rolling without slip (omega0 = v0/r about n x the throw): no closed form");
  if (!th.held()) {
    double speed = th.speed(time), spin = th.spin(time);
    if (spring) {
      if (!(pp.rolling_damping_ratio < 1.0))
        return report_both("the closed form of the spring's start is the underdamped oscillator: eta_r >= 1 has none coded");
      // The spring's elastic start, then the plastic couple: I_c = 1.4 m r^2, C_r = 2 eta_r sqrt(I_c k_r).
      const double inertia_c = 1.4 * m * r * r, c_r = 2.0 * pp.rolling_damping_ratio * std::sqrt(inertia_c * k_r);
      const auto sp = references::spring_rolling(th.v0 / r, m * th.g_t * r, pp.rolling_friction * r_star * m * (-g.dot(n)),
                                                 k_r, c_r, inertia_c, time, ctx.cfg.contact.rolling_limit_with_dashpot);
      if (!sp.limited)
        return report_both("the rolling spring stays below its limit for the whole run: the elastic phase alone has no "
                           "closed form coded here");
      spin = sp.spin(time);
      speed = spin * r;
    }
    // An undamped tangential spring keeps the swing its load's onset starts, which the closed form
    // leaves out: the contact point's slip swings by up to (F_s/k_t) w_t, F_s = m |g_t - a| the steady
    // tangential force, w_t = sqrt(3.5 k_t/m) (about a fixed floor), moving v by 1/3.5 of it and w r by
    // 2.5/3.5 (docs/theory.md 10.5).
    double swing_v = 0.0, swing_w = 0.0;
    std::string swing;
    if (ctx.cfg.contact.tangential == silodem::TangentialModel::LinearHistory && k_t > 0.0 && pp.shear_damping_ratio == 0.0) {
      const double slip = m * std::abs(th.g_t - th.accel) / k_t * std::sqrt(3.5 * k_t / m);
      swing_v = slip / 3.5 / std::max(std::abs(speed), 1e-300);
      swing_w = 2.5 * slip / 3.5 / std::max(std::abs(spin * r), 1e-300);
      swing = "; plus the undamped tangential spring's swing (F_s/k_t) sqrt(3.5 k_t/m) = " + std::to_string(slip) +
              " m/s of slip, 1/3.5 of it in v and 2.5/3.5 in w r (docs/theory.md 10.5)";
    }
    out.push_back(match_row(ctx, "rolling_speed", probe, speed, v.dot(along), t.value + swing_v, t.source.empty() ? t.source : t.source + swing));
    out.push_back(match_row(ctx, "rolling_spin", probe, spin, w.dot(axis), t.value + swing_w, t.source.empty() ? t.source : t.source + swing));
    for (auto& row : out) row.note = "a=" + std::to_string(th.accel) + " m/s^2 once the couple is at its limit";
    return out;
  }
  const double moved = (vec(res.at("final_position")) - grain.position).dot(along);
  if (!spring) {
    out.push_back(report_row(ctx, "held_displacement", probe, moved,
                             "the constant torque's one-step limit lets a held ball creep (docs/model.md 10.5): no bound"));
    return out;
  }
  // Held, the rolling spring carries the couple m g_t r about the contact and the tangential spring
  // the force m g_t; loaded at once from zero, an undamped spring overshoots to twice its static
  // deflection, so the centre moves by at most 2 (r m g_t r / k_r + m g_t / k_t).
  const double load = m * th.g_t;
  const double bound = 2.0 * (r * load * r / k_r + (k_t > 0.0 ? load / k_t : 0.0));
  out.push_back(bound_row(ctx, "held_displacement", probe, std::abs(moved), BoundSide::Upper, bound,
                          "scheme bound: twice the static deflection of the rolling spring k_r = 2.25 k_n mu_r^2 R*^2 "
                          "under the couple m g_t r and of the tangential spring under m g_t (docs/theory.md 10.5); "
                          "free, the ball would roll 5/14 g_t t^2 = " + std::to_string(5.0 / 14.0 * th.g_t * time * time) + " m"));
  return out;
}

void validate_friction_check(const std::string& type, const silodem::JsonReader& r, const CaseConfig& cfg) {
  const auto probe_of = [&](const std::string& key, const std::string& kind) {
    const std::string name = r.string(key);
    for (const auto& p : cfg.probes)
      if (p.name == name && p.type == kind) return;
    r.fail(key, "no " + kind + " probe named \"" + name + "\"");
  };
  const auto fixed_ball = [&](const std::string& key) {
    const std::string id = r.string(key);
    for (const auto& b : cfg.balls)
      if (b.id == id && b.fixed) return;
    r.fail(key, "no fixed ball with id \"" + id + "\"");
  };
  if (type == "hertz_impact") {
    probe_of("pair_probe", "pair");
    if (cfg.contact.normal != silodem::NormalModel::Hertz) r.fail("type", "needs contact.normal \"hertz\"");
  } else {
    probe_of("ball_probe", "ball");
    fixed_ball(type == "oblique_impact" ? "plane" : "floor");
    if (cfg.contact.tangential == silodem::TangentialModel::None) r.fail("type", "needs a tangential law");
    if (type == "rolling_resistance" && cfg.contact.rolling == silodem::RollingModel::None)
      r.fail("type", "needs contact.rolling");
  }
  if (!(r.number("tolerance") > 0.0)) r.fail("tolerance", "must be > 0");
  validate_tolerance_source(r, "tolerance");
}

}  // namespace harness
