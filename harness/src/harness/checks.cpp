#include "harness/checks.hpp"

#include "harness/friction_checks.hpp"
#include "harness/grinding_checks.hpp"
#include "harness/mill_checks.hpp"
#include "harness/tray_checks.hpp"
#include "harness/flow_pattern.hpp"
#include "harness/janssen_prediction.hpp"
#include "harness/angle_of_repose.hpp"
#include "harness/material_checks.hpp"
#include "harness/silo_checks.hpp"
#include "harness/tolerance_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "references/cohesion.hpp"
#include "references/free_fall.hpp"
#include "references/restitution.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/contact/pair_table.hpp"
#include "silodem/contact/stiffest_pair.hpp"

namespace harness {

using nlohmann::json;
using silodem::CaseConfig;
using silodem::Vec3;

const silodem::BallSpec& ball(const CaseConfig& cfg, const std::string& id) {
  for (const auto& b : cfg.balls)
    if (b.id == id) return b;
  throw std::runtime_error("no ball " + id);
}

double mass(const CaseConfig& cfg, const silodem::BallSpec& b) {
  return cfg.materials.at(b.material).density * 4.0 / 3.0 * std::numbers::pi * std::pow(b.radius, 3);
}

namespace {

/// The pair's physics as the case defines it: series constants (11) and effective mass.
struct PairPhysics {
  double k, c, m_eff, m_min;
};
PairPhysics pair_physics(const CaseConfig& cfg, const std::string& a, const std::string& b) {
  const auto& A = ball(cfg, a);
  const auto& B = ball(cfg, b);
  const auto& ma = cfg.materials.at(A.material);
  const auto& mb = cfg.materials.at(B.material);
  const double m_a = mass(cfg, A), m_b = mass(cfg, B);
  return {silodem::contact::series(ma.k, mb.k), silodem::contact::series(ma.c, mb.c),
          silodem::contact::effective_mass(m_a, m_b, A.fixed, B.fixed), std::min(m_a, m_b)};
}

std::vector<std::string> pair_probes(const json& spec, const RunContext& ctx) {
  std::vector<std::string> names;
  if (spec.contains("probes")) return spec["probes"].get<std::vector<std::string>>();
  for (const auto& p : ctx.cfg.probes)
    if (p.type == "pair") names.push_back(p.name);
  return names;
}

const silodem::ProbeSpec& probe_spec(const CaseConfig& cfg, const std::string& name) {
  for (const auto& p : cfg.probes)
    if (p.name == name) return p;
  throw std::runtime_error("no probe " + name);
}

const char* const kCollisionBound =
    "3ζΩ + Ω²/8 + 0.5Ω³ on one collision, Ω = Δt·ω0 of the pair (references/restitution.hpp, docs/theory.md §8)";
const char* const kReboundBound =
    "2(3ζΩ + Ω²/8 + 0.5Ω³): the rise goes with e², and e is within the bound of one collision, Ω = Δt·ω0 "
    "(references/restitution.hpp, docs/theory.md §1c, §8)";

/// A check's tolerance and its source: "scheme_bound" is the bound the check computes, with its
/// derivation; a number comes with the source the case file gives beside it ("" if none).
struct Tolerance {
  double value;
  std::string source;
};
Tolerance tolerance_of(const json& spec, double scheme_bound, const std::string& derivation) {
  const json& t = spec.at("tolerance");
  if (t.is_string()) return {scheme_bound, "scheme bound " + derivation};
  return {t.get<double>(), tolerance_source(spec, "tolerance", t.get<double>())};
}

/// A scheme whose dashpot sees the half-step velocity (LAMMPS, LIGGGHTS, YADE, velocity Verlet with
/// dashpot_velocity = half_step) behaves, to first order, like the exact law with the inertia
/// m_eff − c Δt/2 (references/restitution.hpp); theory then compares with that closed form.
bool lagged_dashpot(const CaseConfig& cfg) {
  return cfg.integrator.scheme == silodem::Scheme::VelocityVerlet && cfg.integrator.half_step_dashpot;
}

std::vector<CheckRow> restitution(const json& spec, const RunContext& ctx) {
  std::vector<CheckRow> out;
  // "exact": the paper's law whatever the scheme, so that a lagged dashpot's own first-order shift
  // counts as error (work against precision compares every scheme with one truth).
  const bool lagged = lagged_dashpot(ctx.cfg) && spec.value("oracle", std::string("as_integrated")) != "exact";
  for (const auto& name : pair_probes(spec, ctx)) {
    const auto& ps = probe_spec(ctx.cfg, name);
    const PairPhysics pp = pair_physics(ctx.cfg, ps.balls[0], ps.balls[1]);
    const auto th = lagged
                        ? references::kelvin_voigt_collision_lagged(pp.k, pp.c, pp.m_eff, ctx.cfg.contact.clamp,
                                                                    ctx.cfg.dt)
                        : references::kelvin_voigt_collision(pp.k, pp.c, pp.m_eff, ctx.cfg.contact.clamp);
    const Tolerance tol =
        tolerance_of(spec, references::scheme_error_bound(th.zeta, ctx.cfg.dt * th.omega0), kCollisionBound);
    const CsvTable ev = ctx.result.probe(name);
    // An empty restitution cell: the contact was there from the first sample without approaching.
    if (ev.size() == 0 || ev.number(0, "ended") != 1.0 || ev.text(0, "restitution").empty()) {
      CheckRow r = match_row(ctx, "restitution", name, th.restitution, NAN, tol.value, tol.source);
      r.note = ev.size() == 0 || ev.number(0, "ended") != 1.0 ? "no completed contact"
                                                              : "the first contact had no approach (present at t = 0)";
      out.push_back(r);
      continue;
    }
    const std::string zeta = "zeta=" + std::to_string(th.zeta);
    out.push_back(match_row(ctx, "restitution", name, th.restitution, ev.number(0, "restitution"), tol.value, tol.source));
    out.back().note = zeta;
    out.push_back(match_row(ctx, "contact_duration", name, th.duration, ev.number(0, "duration"), tol.value, tol.source));
    out.back().note = zeta;
  }
  return out;
}

/// A pair of the cohesion checks with its closed form and the scheme's Ω = Δt ω_c.
struct CohesionCase {
  references::CohesionPair th;
  double omega_dt, u0, k, m_eff, largest_coordinate;
};
CohesionCase cohesion_case(const RunContext& ctx, const std::string& probe) {
  const auto& ps = probe_spec(ctx.cfg, probe);
  const auto& A = ball(ctx.cfg, ps.balls[0]);
  const auto& B = ball(ctx.cfg, ps.balls[1]);
  const PairPhysics pp = pair_physics(ctx.cfg, A.id, B.id);
  const double u0 = (A.velocity - B.velocity).dot((A.position - B.position).normalized());  // separation speed at t = 0
  const auto th = references::cohesion_separation(pp.k, pp.m_eff, pp.m_min, ctx.cfg.contact.p_n,
                                                  ctx.cfg.gravity.norm(), u0);
  const double largest = std::max(A.position.cwiseAbs().maxCoeff(), B.position.cwiseAbs().maxCoeff());
  return {th, ctx.cfg.dt * std::sqrt(pp.k / pp.m_eff), u0, pp.k, pp.m_eff, largest};
}

std::vector<CheckRow> cohesion_separation(const json& spec, const RunContext& ctx) {
  std::vector<CheckRow> out;
  for (const auto& name : pair_probes(spec, ctx)) {
    const CohesionCase cc = cohesion_case(ctx, name);
    const json& d = ctx.result.probe_digest(name);
    const std::string note = "u0/v*=" + std::to_string(cc.u0 / cc.th.escape_speed) + ", Omega=" + std::to_string(cc.omega_dt);
    if (cc.th.escapes) {
      const Tolerance tol = tolerance_of(spec, references::escape_speed_bound(cc.th, cc.omega_dt),
                                         "Ω v*/v_f + Ω²/8 + 0.5Ω³: the zone's edge seen up to one step late "
                                         "(references/cohesion.hpp)");
      out.push_back(match_row(ctx, "escape_speed", name, cc.th.final_speed, -d.at("final_overlap_rate").get<double>(),
                              tol.value, tol.source));
    } else {
      const Tolerance tol =
          tolerance_of(spec, references::turning_gap_bound(cc.th, cc.omega_dt, cc.largest_coordinate),
                       "2(Ω²/8 + 0.5Ω³) + position rounding over the (π/2)/Ω steps to the turn (references/cohesion.hpp)");
      out.push_back(match_row(ctx, "turning_gap", name, cc.th.turning_gap, d.at("max_gap").get<double>(), tol.value, tol.source));
      out.back().note = note;
      // The captured pair never reaches the zone's edge |δ_c|.
      out.push_back(bound_row(ctx, "captured_gap/reach", name, d.at("max_gap").get<double>() / cc.th.reach,
                              BoundSide::Upper, 1.0,
                              "closed form: a pair with u0 < v* turns at u0/ω_c < |δ_c| (docs/theory.md §2a)"));
    }
    out.back().note = note;
  }
  return out;
}

/// The ledger's cohesion term against theory: an escaping pair leaves ½ k δ_c² behind, a captured
/// pair all of its relative kinetic energy ½ m_eff u0² (its spring lets go at the turning point).
std::vector<CheckRow> cohesion_energy(const json& spec, const RunContext& ctx) {
  double expected = 0.0, bound = 0.0;
  for (const auto& name : pair_probes(spec, ctx)) {
    const CohesionCase cc = cohesion_case(ctx, name);
    const double reach = cc.th.reach;
    expected += cc.th.escapes ? 0.5 * cc.k * reach * reach : 0.5 * cc.m_eff * cc.u0 * cc.u0;
    // Every term within its own relative bound: the sum within the largest.
    bound = std::max(bound, references::cohesion_energy_bound(cc.th, cc.omega_dt, cc.largest_coordinate));
  }
  const double measured = ctx.result.summary.at("energy").at("cohesion_removed").get<double>();
  const Tolerance tol = tolerance_of(spec, bound,
                                     "the largest over the pairs of 2Ω v_f/v* + Ω²/8 + 0.5Ω³ (escaped) or twice the "
                                     "turning-gap bound (captured) (references/cohesion.hpp)");
  CheckRow r = match_row(ctx, "cohesion_energy_removed", "ledger", expected, measured, tol.value, tol.source);
  r.note = "sum over pairs: escaped 1/2 k dc^2, captured 1/2 m_eff u0^2";
  return {r};
}

std::vector<CheckRow> first_contact(const json& spec, const RunContext& ctx) {
  std::vector<CheckRow> out;
  const double g = ctx.cfg.gravity.norm();
  // The analytic drop (Algorithm 2).
  const CsvTable drops = ctx.result.probe(spec.at("drops_probe").get<std::string>());
  const std::size_t k = spec.value("drop", 0);
  const std::string want = spec.at("obstacle").get<std::string>();
  const auto& ob = ball(ctx.cfg, want);
  const std::string drop = "drop " + std::to_string(k);
  CheckRow pick = match_row(ctx, "drop_obstacle", drop, 1.0, drops.text(k, "obstacle") == want ? 1.0 : 0.0, 0.0,
                            "exact: Algorithm 2 chooses the obstacle in closed form (yes = 1, no = 0)", false);
  pick.note = "expected " + want + ", found " + drops.text(k, "obstacle");
  out.push_back(pick);
  const double x0 = drops.number(k, "x0"), y0 = drops.number(k, "y0"), r0 = drops.number(k, "r");
  const double b = std::hypot(x0 - ob.position.x(), y0 - ob.position.y());
  const double zc = references::contact_height_above(b, r0 + ob.radius);
  out.push_back(match_row(ctx, "drop_contact_height", drop, zc, drops.number(k, "z") - ob.position.z(), 1e-9,
                          "rounding: Algorithm 2 places the drop at √(R² − b²) in closed form; 1e-9 is far above "
                          "double rounding of that expression (1e-16 times its condition)"));
  // The integrated twin: released at rest, its first contact must be with the twin obstacle at the
  // same height above it, to within one step's travel.
  const json& tw = spec.at("twin");
  const std::string twin_pair = tw.at("pair_probe").get<std::string>();
  const auto& tps = probe_spec(ctx.cfg, twin_pair);
  const auto& faller = ball(ctx.cfg, tps.balls[0]);
  const auto& tob = ball(ctx.cfg, tps.balls[1]);
  const CsvTable ev = ctx.result.probe(twin_pair);
  const double tb = std::hypot(faller.position.x() - tob.position.x(), faller.position.y() - tob.position.y());
  const double tzc = references::contact_height_above(tb, faller.radius + tob.radius);
  const double H = faller.position.z() - tob.position.z() - tzc;
  const double step_travel = std::sqrt(2.0 * g * H) * ctx.cfg.dt;
  double t_on = ev.size() ? ev.number(0, "t_start") : NAN;
  // Free fall from rest is integrated exactly by every scheme here (constant acceleration), so the
  // contact time fixes the contact height.
  const double z_on = faller.position.z() - 0.5 * g * t_on * t_on - tob.position.z();
  CheckRow tr = match_row(ctx, "integrated_contact_height", twin_pair, tzc, z_on, step_travel,
                          "scheme bound √(2gH)·Δt: the contact is seen at the first step in overlap, at most one "
                          "step's travel late (free fall itself is integrated exactly)",
                          false);
  tr.note = "tolerance = one step's travel";
  out.push_back(tr);
  for (const auto& other : tw.value("other_pair_probes", std::vector<std::string>{})) {
    const CsvTable oe = ctx.result.probe(other);
    const double t_other = oe.size() ? oe.number(0, "t_start") : INFINITY;
    CheckRow o = match_row(ctx, "integrated_first_obstacle", other, 1.0, t_other > t_on ? 1.0 : 0.0, 0.0,
                           "exact: the closed-form first contact is the expected obstacle (yes = 1, no = 0)", false);
    o.note = "touched after the expected obstacle (or never)";
    out.push_back(o);
  }
  return out;
}

std::vector<CheckRow> rebound_height(const json& spec, const RunContext& ctx) {
  const double g = ctx.cfg.gravity.norm();
  const std::string probe = spec.at("ball_probe").get<std::string>();
  const std::string id = probe_spec(ctx.cfg, probe).balls[0];
  const std::string obstacle = spec.at("obstacle").get<std::string>();
  const auto& ob = ball(ctx.cfg, obstacle);
  // The falling ball is a listed ball released at rest.
  const silodem::BallSpec& faller = ball(ctx.cfg, id);
  const double release = faller.position.z(), r = faller.radius;
  const auto& mf = ctx.cfg.materials.at(faller.material);
  const auto& mo = ctx.cfg.materials.at(ob.material);
  const double m = mf.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double k = silodem::contact::series(mf.k, mo.k), c = silodem::contact::series(mf.c, mo.c);
  const double z_contact = ob.position.z() + r + ob.radius;  // head-on: b = 0
  const double H = release - z_contact, v1 = std::sqrt(2.0 * g * H);
  // With a lagged dashpot the contact behaves as if its inertia were m − c Δt/2, gravity unchanged.
  const double m_in = lagged_dashpot(ctx.cfg) ? m - 0.5 * c * ctx.cfg.dt : m;
  const double eg = references::restitution_with_gravity(k, c, m_in, v1, g * m / m_in, ctx.cfg.contact.clamp);
  const double expected_rise = eg * eg * H;
  const auto th = references::kelvin_voigt_collision(k, c, m_in, ctx.cfg.contact.clamp);
  // The rise goes with e², so the scheme bound on e doubles; a numeric tolerance applies as given.
  const double bound = references::scheme_error_bound(th.zeta, ctx.cfg.dt * th.omega0);
  const Tolerance tol = tolerance_of(spec, 2.0 * bound, kReboundBound);
  const CsvTable ap = ctx.result.probe(probe);
  const double measured = ap.size() ? ap.number(0, "height") - z_contact : NAN;
  CheckRow rr = match_row(ctx, "rebound_height", probe, expected_rise, measured, tol.value, tol.source);
  rr.note = "e_g=" + std::to_string(eg) + " (gravity-corrected), H=" + std::to_string(H);
  return {rr};
}

/// A ledger rebuilt from dump frames (reference codes, and silodem's reconstructed/) integrates
/// the dashpot power over the frames, not the steps.
std::vector<CheckRow> energy_balance(const json& spec, const RunContext& ctx) {
  if (ctx.result.summary.at("energy").contains("not_reconstructible"))
    return {report_row(ctx, "energy_drift", "ledger", NAN,
                       "partial ledger: " + ctx.result.summary.at("energy").at("partial").get<std::string>())};
  const double drift = ctx.result.summary.at("energy").at("max_abs_relative_drift").get<double>();
  const long frame_steps = std::max(1L, ctx.cfg.dump_interval_steps);
  const bool rebuilt = ctx.result.summary.contains("reconstructed_from");
  if (rebuilt && frame_steps > 1) {
    char why[300];
    std::snprintf(why, sizeof why,
                  "ledger rebuilt from dump frames every %ld steps (%.3g frames per shortest contact): the dashpot "
                  "work between frames is interpolated, and no error bound is derived for that",
                  frame_steps, energy_frames_per_contact(ctx.cfg));
    return {report_row(ctx, "energy_drift", "ledger", drift, why, 0.0)};
  }
  const double tol = spec.at("tolerance").get<double>();
  CheckRow r = bound_row(ctx, "energy_drift", "ledger", drift, BoundSide::Upper, tol, tolerance_source(spec, "tolerance", tol));
  r.expected = 0.0;
  r.note = rebuilt ? "max |balance| / energy moved, rebuilt from a dump of every step" : "max |balance| / energy moved";
  return {r};
}

/// The final ledger as fractions of one scale, for between_codes (issue 4: "compare energy
/// ledgers"). Only state functions and the energy that left the mechanical system: the rebuilt
/// ledgers of the reference codes integrate the dashpot power over dump frames, too coarse to
/// compare — and so is their "energy moved", which is why the scale here is made of state
/// functions too: the largest of |ΔE_grav| and the kinetic and elastic energy at start and end.
std::vector<CheckRow> energy_terms(const json&, const RunContext& ctx) {
  const json& e = ctx.result.summary.at("energy");
  const CsvTable series = read_csv(ctx.result.dir / "series.csv");
  if (series.size() == 0) throw std::runtime_error("energy_terms: " + (ctx.result.dir / "series.csv").string() + " has no rows");
  const double kin = e.at("kinetic").get<double>(), grav = e.at("gravitational").get<double>(), el = e.at("elastic").get<double>();
  const double lost = e.at("initial").get<double>() + e.at("injected").get<double>() - e.at("withdrawn").get<double>() -
                      (kin + grav + el);
  const double d_grav = grav - series.number(0, "E_grav");
  const double scale = std::max({std::abs(d_grav), kin, el, series.number(0, "E_kin"), series.number(0, "E_el")});
  const std::pair<const char*, double> terms[] = {
      {"energy_kinetic", kin}, {"energy_elastic", el}, {"energy_gravitational_change", d_grav}, {"energy_lost", lost}};
  // A partial ledger (a rebuilt one without the springs' history) has no complete elastic or lost term.
  const bool partial = e.contains("not_reconstructible");
  std::vector<CheckRow> out;
  for (const auto& [q, v] : terms) {
    const bool incomplete = partial && (std::string(q) == "energy_elastic" || std::string(q) == "energy_lost");
    CheckRow r = report_row(ctx, q, "final / state scale", scale > 0.0 && !incomplete ? v / scale : NAN,
                            incomplete ? "partial ledger: " + e.at("partial").get<std::string>()
                                       : "a fraction of the state scale, compared between codes (between_codes); no oracle alone");
    r.note = "scale " + std::to_string(scale) +
             " J = max(|ΔE_grav|, E_kin and E_el at start and end); lost = initial + injected − withdrawn − final";
    out.push_back(r);
  }
  return out;
}

CheckRow labelled(const RunContext& ctx, std::string quantity, std::string subject) {
  CheckRow r;
  r.case_name = ctx.cfg.name;
  r.variant = ctx.variant;
  r.code = ctx.code;
  r.quantity = std::move(quantity);
  r.subject = std::move(subject);
  return r;
}

}  // namespace

CheckRow match_row(const RunContext& ctx, std::string quantity, std::string subject, double expected, double measured,
                   double tolerance, std::string source, bool relative) {
  CheckRow r = labelled(ctx, std::move(quantity), std::move(subject));
  r.kind = RowKind::Match;
  r.expected = expected;
  r.measured = measured;
  r.error = relative ? (measured - expected) / expected : measured - expected;
  r.tolerance = tolerance;
  r.tolerance_source = std::move(source);
  judge(r);
  return r;
}

CheckRow bound_row(const RunContext& ctx, std::string quantity, std::string subject, double measured, BoundSide side,
                   double bound, std::string source) {
  CheckRow r = labelled(ctx, std::move(quantity), std::move(subject));
  r.kind = RowKind::Bound;
  r.measured = measured;
  r.side = side;
  r.bound = bound;
  r.tolerance_source = std::move(source);
  judge(r);
  return r;
}

CheckRow report_row(const RunContext& ctx, std::string quantity, std::string subject, double measured,
                    std::string reason, double expected) {
  CheckRow r = labelled(ctx, std::move(quantity), std::move(subject));
  r.expected = expected;
  r.measured = measured;
  to_report(r, std::move(reason));
  return r;
}

namespace {
const char* const kFrictionless = "frictionless grains: ";
}

std::string frictionless_reason(const std::string& what) {
  return kFrictionless + what +
         " are published for frictional grains only (docs/theory.md §4-6); reported, not judged, until the model has "
         "contact friction";
}

bool is_frictionless_report(const CheckRow& r) {
  return r.kind == RowKind::Report && r.reason.rfind(kFrictionless, 0) == 0;
}

bool frictional_grains(const CaseConfig& cfg) {
  // A tangential law, and friction between two mobile balls of the scene (walls alone do not make
  // a granular material frictional).
  if (cfg.contact.tangential == silodem::TangentialModel::None) return false;
  const auto table = silodem::contact::pair_table(cfg);
  for (const auto& kind : silodem::kind_pairs(cfg))
    if (kind.both_mobile && table.at(kind.material_a, kind.material_b).friction > 0.0) return true;
  return false;
}

double energy_frames_per_contact(const CaseConfig& cfg) {
  double shortest = INFINITY;
  for (const auto& p : silodem::contact_pairs(cfg))
    if (std::isfinite(p.behaviour.duration)) shortest = std::min(shortest, p.behaviour.duration);
  return shortest / (double(std::max(1L, cfg.dump_interval_steps)) * cfg.dt);
}

double column_floor(const CaseConfig& cfg, const json& geometry) {
  const double z_base = geometry.at("centre")[2], top = z_base + geometry.at("height").get<double>();
  double floor = INFINITY;
  for (const auto& w : cfg.walls)
    if (w.type == "disk" && w.centre.z() >= z_base && w.centre.z() < top)
      floor = std::min(floor, w.centre.z());
  return std::isfinite(floor) ? floor : z_base;
}

double outlet_diameter_of(const CaseConfig& cfg, const std::string& name) {
  for (const auto& w : cfg.walls)
    if (w.name == name) return w.hole_diameter;
  for (const auto& s : cfg.surfaces)  // a hopper's smooth wall: its lower end is the outlet
    if (s.name == name) return 2.0 * (s.z0 < s.z1 ? s.rho0 : s.rho1);
  return 0.0;
}

double outlet_diameter(const json& spec, const CaseConfig& cfg) {
  const std::string wall = spec.at("outlet_wall");
  const double d = outlet_diameter_of(cfg, wall);
  if (!(d > 0.0)) throw std::runtime_error("no wall " + wall + " with an outlet");
  return d;
}

std::vector<CheckRow> run_check(const json& spec, const RunContext& ctx) {
  const std::string type = spec.at("type");
  if (type == "restitution") return restitution(spec, ctx);
  if (type == "cohesion_separation") return cohesion_separation(spec, ctx);
  if (type == "cohesion_energy") return cohesion_energy(spec, ctx);
  if (type == "first_contact") return first_contact(spec, ctx);
  if (type == "rebound_height") return rebound_height(spec, ctx);
  if (type == "energy_balance") return energy_balance(spec, ctx);
  if (type == "energy_terms") return energy_terms(spec, ctx);
  if (type == "janssen") return janssen(spec, ctx);
  if (type == "beverloo") return beverloo(spec, ctx);
  if (type == "closure_overpressure") return closure_overpressure(spec, ctx);
  if (type == "pressure_profile") return pressure_profile(spec, ctx);
  if (type == "discharge_factor") return discharge_factor(spec, ctx);
  if (type == "static_balance") return static_balance(spec, ctx);
  if (type == "hertz_impact") return hertz_impact(spec, ctx);
  if (type == "oblique_impact") return oblique_impact(spec, ctx);
  if (type == "slip_to_roll") return slip_to_roll(spec, ctx);
  if (type == "rolling_resistance") return rolling_resistance(spec, ctx);
  if (type == "lateral_pressure_ratio") return lateral_pressure_ratio(spec, ctx);
  if (type == "wall_friction") return wall_friction(spec, ctx);
  if (type == "direct_shear") return direct_shear(spec, ctx);
  if (type == "angle_of_repose") return angle_of_repose(spec, ctx);
  if (type == "janssen_prediction") return janssen_prediction(spec, ctx);
  if (type == "flow_pattern") return flow_pattern(spec, ctx);
  if (type == "torque_identity") return torque_identity(spec, ctx);
  if (type == "mill_regime") return mill_regime(spec, ctx);
  if (type == "charge_volume") return charge_volume(spec, ctx);
  if (type == "size_distribution") return size_distribution(spec, ctx);
  if (type == "slot_discharge") return slot_discharge(spec, ctx);
  return {};
}

std::vector<CheckRow> run_checks(const json& checks, const RunContext& ctx) {
  std::vector<CheckRow> rows;
  for (const auto& spec : checks) {
    auto r = run_check(spec, ctx);
    rows.insert(rows.end(), r.begin(), r.end());
  }
  return rows;
}

}  // namespace harness
