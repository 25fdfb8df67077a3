// YADE 2023.02a (Debian `yade`): the only C++ file that knows YADE: which of its laws a case maps to
// (viscoelastic, Hertz–Mindlin or CohFrictMat's moment law, with friction per type pair) and the constants; the rest is in the
// driver (harness/yade/yade_driver.py), embedded into the binary and written next to its input.
// Run as a Python module under /usr/bin/python3.11, not through the `yade` launcher, which binds
// ports 9000 and 21000 on all interfaces (docs/reference-codes.md, Measured facts: YADE).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "harness/backends/reference_backend.hpp"
#include "harness/backends/subprocess.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "yade_driver_source.hpp"

namespace harness {

namespace {

constexpr const char* kPython = "/usr/bin/python3.11";
constexpr const char* kYadeLib = "/usr/lib/x86_64-linux-gnu/yade-double/py";

/// YADE's three laws for what silodem computes: "viscoelastic" (ViscElMat, Law2_ScGeom_ViscElPhys_Basic:
/// the paper's linear law, with a tangential history spring when the case has one), "hertz_mindlin"
/// (FrictMat, Law2_ScGeom_MindlinPhys_Mindlin) or, with the EPSD rolling spring, "moment"
/// (CohFrictMat, Law2_ScGeom6D_CohFrictPhys_CohesionMoment: undamped only).
bool hertz(const silodem::CaseConfig& cfg) { return cfg.contact.normal == silodem::NormalModel::Hertz; }
bool moment_law(const silodem::CaseConfig& cfg) { return cfg.contact.rolling == silodem::RollingModel::Spring; }
const char* law_name(const silodem::CaseConfig& cfg) {
  return hertz(cfg) ? "hertz_mindlin" : moment_law(cfg) ? "moment" : "viscoelastic";
}

/// YADE combines a ViscElMat's constants per material in series, skipping a zero one (a with 0
/// gives a, where (11) gives 0): silodem's pair value must be the series of per-type values. A
/// zero is replaced by 1e-12 x the largest, whose pairs then carry ~1e-12 of it.
std::vector<double> nonzero(std::vector<double> v) {
  const double top = *std::max_element(v.begin(), v.end());
  for (double& x : v)
    if (!(x > 0.0)) x = 1e-12 * top;
  return v;
}

/// Whether any pair has a normal dashpot: without one the force is never tensile, so the clamp
/// YADE always applies changes nothing.
bool damped(const silodem::CaseConfig& cfg, const Translation& tr) {
  for (int a = 1; a <= int(tr.types.size()); ++a)
    for (int b = a; b <= int(tr.types.size()); ++b)
      if (hertz(cfg) ? tr.pair(a, b).hertz_zeta > 0.0 : tr.pair_c(a, b) > 0.0) return true;
  return false;
}

struct ViscoelasticTypes {
  std::vector<double> k, c, ks, cs;  // per type
  std::string why_not;               // empty when every touching pair is reproduced
};

/// Per type: k_i, c_i as the translation has them; ks_i = (k_t/k_n) k_i and cs_i = (gamma_t/c_n) c_i from
/// the type's own material pair, checked against every pair that can touch (not two walls).
ViscoelasticTypes viscoelastic_types(const silodem::CaseConfig& cfg, const Translation& tr) {
  ViscoelasticTypes v;
  const bool spring = cfg.contact.tangential == silodem::TangentialModel::LinearHistory;
  for (std::size_t t = 0; t < tr.types.size(); ++t) {
    const int a = int(t) + 1;
    v.k.push_back(tr.types[t].k);
    v.c.push_back(tr.types[t].c);
    v.ks.push_back(spring ? tr.pair(a, a).shear_ratio * tr.types[t].k : 0.0);
    v.cs.push_back(spring ? tr.pair(a, a).shear_damping_ratio * tr.types[t].c : 0.0);
  }
  v.c = nonzero(v.c);
  if (!spring) return v;
  v.cs = nonzero(v.cs);
  for (std::size_t a = 0; a < tr.types.size(); ++a)
    for (std::size_t b = a; b < tr.types.size(); ++b) {
      if (tr.types[a].fixed && tr.types[b].fixed) continue;
      const auto& pp = tr.pair(int(a) + 1, int(b) + 1);
      const double ks = silodem::contact::series(v.ks[a], v.ks[b]), want_ks = pp.shear_ratio * tr.pair_k(int(a) + 1, int(b) + 1);
      const double cs = silodem::contact::series(v.cs[a], v.cs[b]);
      const double want_cs = pp.shear_damping_ratio * tr.pair_c(int(a) + 1, int(b) + 1);
      const auto off = [](double x, double want) { return std::abs(x - want) > 1e-9 * std::max(std::abs(want), 1e-300); };
      if (!(v.ks[a] > 0.0) || off(ks, want_ks) || (want_cs > 0.0 && off(cs, want_cs)))
        v.why_not = "YADE combines ViscElMat's ks and cs per material in series: the pair " + tr.types[a].material +
                    "-" + tr.types[b].material + " has k_t or gamma_t that no per-material values reproduce "
                    "(different k_t/k_n or gamma_t/c_n ratios per material pair)";
    }
  return v;
}

struct MomentLawTypes {
  std::vector<double> young, poisson, alpha_kr, eta_roll;  // per type
  std::string why_not;                                     // empty when every touching pair is reproduced
};

/// YADE's harmonic mean of two materials' alphaKr (zero if either is).
double harmonic(double x, double y) { return x > 0.0 && y > 0.0 ? 2.0 * x * y / (x + y) : 0.0; }

/// Per-type alphaKr such that every touching pair's harmonic mean is `target(a, b)`: a type touching
/// itself takes its own pair's value, the others are solved from a known partner, H(x, y) = T gives
/// y = T x / (2x - T); a pair of two unknown types takes T on both.
std::vector<double> solve_alpha(const Translation& tr, const std::function<double(int, int)>& target) {
  const int n = int(tr.types.size());
  std::vector<double> alpha(std::size_t(n), NAN);
  for (int a = 1; a <= n; ++a)
    if (tr.can_touch(a, a)) alpha[std::size_t(a - 1)] = target(a, a);
  for (bool open = true; open;) {
    open = false;
    bool solved = false;
    for (int a = 1; a <= n && !solved; ++a)
      for (int b = 1; b <= n && !solved; ++b) {
        const double x = alpha[std::size_t(a - 1)], t = target(a, b);
        if (a == b || !tr.can_touch(a, b) || std::isnan(x) || !std::isnan(alpha[std::size_t(b - 1)])) continue;
        alpha[std::size_t(b - 1)] = t == 0.0 ? 0.0 : 2.0 * x > t ? t * x / (2.0 * x - t) : -1.0;
        solved = open = true;
      }
    for (int a = 1; a <= n && !solved; ++a)
      for (int b = a + 1; b <= n && !solved; ++b)
        if (tr.can_touch(a, b) && std::isnan(alpha[std::size_t(a - 1)]) && std::isnan(alpha[std::size_t(b - 1)]))
          alpha[std::size_t(a - 1)] = alpha[std::size_t(b - 1)] = target(a, b), solved = open = true;
  }
  for (double& x : alpha)
    if (std::isnan(x)) x = 0.0;  // a type that touches nothing
  return alpha;
}

/// CohFrictMat per type for silodem's linear law with tangential history and the EPSD rolling
/// spring, from YADE's Ip2_CohFrictMat_CohFrictMat_CohFrictPhys (docs/reference-codes.md, "YADE
/// CohFrictMat"): k_n is the series of 2 E_i R_i, so E_i = k_i/(2 R_i); k_s the series of 2 nu_i E_i R_i,
/// so nu_i = k_t/k_n; k_r = R_1 R_2 k_s times the harmonic mean of alphaKr, and silodem's
/// k_r = 2.25 k_n mu_r^2 R*^2 wants alphaKr pairs with the mean 2.25 mu_r^2 R*^2/(nu R_1 R_2); the
/// limit length min(etaRoll_i R_i) must be mu_r R*. One radius per type, checked on every touching pair.
MomentLawTypes moment_law_types(const Translation& tr) {
  MomentLawTypes v;
  const int n = int(tr.types.size());
  std::vector<double> radius(std::size_t(n), 0.0);
  for (int a = 1; a <= n; ++a) {
    const auto radii = tr.type_radii(a);
    if (radii.size() > 1) {
      v.why_not = "YADE's CohFrictMat takes the radius into its stiffnesses: the translation needs one radius per "
                  "particle type, and " + tr.types[std::size_t(a - 1)].material + " has " + std::to_string(radii.size());
      return v;
    }
    radius[std::size_t(a - 1)] = radii.empty() ? 1.0 : *radii.begin();
  }
  const auto r_star = [&](int a, int b) {
    return radius[std::size_t(a - 1)] * radius[std::size_t(b - 1)] / (radius[std::size_t(a - 1)] + radius[std::size_t(b - 1)]);
  };
  double nu = NAN;
  for (int a = 1; a <= n; ++a)
    for (int b = a; b <= n; ++b)
      if (tr.can_touch(a, b)) {
        if (std::isnan(nu)) nu = tr.pair(a, b).shear_ratio;
        if (tr.pair(a, b).shear_ratio != nu || !(nu > 0.0))
          v.why_not = "YADE's CohFrictMat shear stiffness is the series of 2 nu_i E_i R_i: the translation needs one "
                      "k_t/k_n > 0 for every pair";
      }
  const auto alpha_target = [&](int a, int b) {
    const double mu_r = tr.pair(a, b).rolling_friction, rs = r_star(a, b);
    return 2.25 * mu_r * mu_r * rs * rs / (nu * radius[std::size_t(a - 1)] * radius[std::size_t(b - 1)]);
  };
  v.alpha_kr = solve_alpha(tr, alpha_target);
  std::vector<double> length(std::size_t(n), 0.0);  // etaRoll_i R_i: the smallest each type's pairs allow
  std::vector<bool> touches(std::size_t(n), false);
  for (int a = 1; a <= n; ++a)
    for (int b = 1; b <= n; ++b)
      if (tr.can_touch(a, b))
        length[std::size_t(a - 1)] = std::max(length[std::size_t(a - 1)], tr.pair(a, b).rolling_friction * r_star(a, b)),
        touches[std::size_t(a - 1)] = true;
  const auto off = [](double x, double want) { return std::abs(x - want) > 1e-9 * std::abs(want); };
  for (int a = 1; a <= n; ++a) {
    const auto& t = tr.types[std::size_t(a - 1)];
    v.young.push_back(t.k / (2.0 * radius[std::size_t(a - 1)]));
    v.poisson.push_back(std::isnan(nu) ? 0.0 : nu);
    v.eta_roll.push_back(touches[std::size_t(a - 1)] ? length[std::size_t(a - 1)] / radius[std::size_t(a - 1)] : -1.0);
    for (int b = a; b <= n; ++b)
      if (tr.can_touch(a, b) && v.why_not.empty() &&
          (off(harmonic(v.alpha_kr[std::size_t(a - 1)], v.alpha_kr[std::size_t(b - 1)]), alpha_target(a, b)) ||
           off(std::min(length[std::size_t(a - 1)], length[std::size_t(b - 1)]), tr.pair(a, b).rolling_friction * r_star(a, b))))
        v.why_not = "YADE's CohFrictMat combines the rolling stiffness (harmonic mean of alphaKr) and the rolling limit "
                    "(min of etaRoll_i R_i) per material: the pair " + t.material + "-" + tr.types[std::size_t(b - 1)].material +
                    " has k_r or mu_r R* that no per-material values reproduce together with the other pairs";
  }
  return v;
}

/// The moment law has no viscous term: a pair with any dashpot (normal, tangential or rolling) is not its case.
std::string moment_law_limits(const silodem::CaseConfig& cfg, const Translation& tr) {
  const auto& c = cfg.contact;
  if (c.normal != silodem::NormalModel::Linear || c.tangential != silodem::TangentialModel::LinearHistory)
    return "YADE's moment law (CohFrictMat) is translated for the linear law with tangential history only";
  if (c.slip_arm_radius)
    return "YADE's moment law takes the slip velocity at the contact point; contact.slip_lever_arm \"radius\" is LAMMPS's form";
  for (int a = 1; a <= int(tr.types.size()); ++a)
    for (int b = a; b <= int(tr.types.size()); ++b)
      if (tr.can_touch(a, b) && (tr.pair_c(a, b) > 0.0 || tr.pair(a, b).shear_damping_ratio > 0.0 ||
                                 tr.pair(a, b).rolling_damping_ratio > 0.0))
        return "YADE's rolling spring (CohFrictMat's moment law) has no dashpot, normal, tangential or rolling: only an "
               "undamped case (restitution 1, tangential and rolling damping 0) is translated, and the pair " +
               tr.types[std::size_t(a - 1)].material + "-" + tr.types[std::size_t(b - 1)].material + " is damped";
  return moment_law_types(tr).why_not;
}

class YadeBackend final : public ReferenceBackend {
 public:
  std::string code() const override { return "yade"; }
  std::string missing() const override {
    if (::access(kPython, X_OK) != 0) return std::string(kPython) + " not found";
    if (!std::filesystem::exists(std::string(kYadeLib) + "/yade")) return std::string("yade not found (") + kYadeLib + ")";
    return "";
  }

 protected:
  std::string code_limits(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    if (!cfg.surfaces.empty())
      return "smooth walls (\"surfaces\") are not translated for YADE: its facets touch a ball once per facet within reach, "
             "so a mesh pushes two or three times where silodem's surface pushes once (measured: e 0.16-0.30 for 0.40; "
             "docs/reference-codes.md, smooth walls)";
    const auto& c = cfg.contact;
    if (c.rolling == silodem::RollingModel::ConstantTorque)
      return "YADE has no constant rolling torque: ViscElMat's mR is a rotational damper (-mR |N| (w1 - w2), the spin "
             "difference not normalised) and CohFrictMat's moment law a spring (docs/reference-codes.md, sub-models by code)";
    if (moment_law(cfg)) return moment_law_limits(cfg, tr);
    if (c.tangential == silodem::TangentialModel::CoulombSliding)
      return "YADE has no sliding-only Coulomb law (its laws keep a tangential spring)";
    if (c.normal == silodem::NormalModel::Linear && c.tangential == silodem::TangentialModel::LinearHistory &&
        c.slip_arm_radius)
      return "YADE's viscoelastic law takes the slip velocity at the contact point; contact.slip_lever_arm "
             "\"radius\" is LAMMPS's form";
    if (!c.clamp && damped(cfg, tr))
      return "YADE always clamps the normal force at zero (its viscoelastic and Hertz-Mindlin laws); "
             "the unclamped damped law has no stock equivalent";
    return hertz(cfg) ? "" : viscoelastic_types(cfg, tr).why_not;
  }

  std::string version(const std::filesystem::path& log) const override {
    std::ifstream in(log);
    std::string l;
    while (std::getline(in, l))
      if (l.rfind("YADE ", 0) == 0) return l;
    return "yade (version not printed)";
  }

 public:
  Input write_input(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    nlohmann::json types = nlohmann::json::array(), pairs = nlohmann::json::array();
    if (moment_law(cfg)) {
      const MomentLawTypes v = moment_law_types(tr);
      for (std::size_t t = 0; t < tr.types.size(); ++t)
        types.push_back({{"young", v.young[t]}, {"poisson", v.poisson[t]}, {"alpha_kr", v.alpha_kr[t]},
                         {"eta_roll", v.eta_roll[t]}, {"density", tr.types[t].density}});
    } else if (hertz(cfg)) {
      for (const auto& t : tr.types) {
        const silodem::Material& m = cfg.materials.at(t.material);
        types.push_back({{"young", m.youngs_modulus}, {"poisson", m.poisson_ratio}, {"density", t.density}});
      }
    } else {
      const ViscoelasticTypes v = viscoelastic_types(cfg, tr);
      for (std::size_t t = 0; t < tr.types.size(); ++t)
        types.push_back({{"k", v.k[t]}, {"c", v.c[t]}, {"ks", v.ks[t]}, {"cs", v.cs[t]}, {"density", tr.types[t].density}});
    }
    // Every type pair: YADE's MatchMakers have no fallback for a pair left out.
    const bool mindlin = cfg.contact.tangential == silodem::TangentialModel::Mindlin;
    for (int a = 1; a <= int(tr.types.size()); ++a)
      for (int b = a; b <= int(tr.types.size()); ++b) {
        const auto& pp = tr.pair(a, b);
        nlohmann::json q = {{"a", a}, {"b", b}, {"friction_angle", std::atan(pp.friction)}};
        if (hertz(cfg)) {
          // silodem's c_n = 2 zeta sqrt(m* S_n), S_n = 2 E* sqrt(R* delta), is YADE's with betan = zeta; its
          // c_t = (gamma_t/c_n) c_n is YADE's 2 betas sqrt(m* k_t), k_t = 8 G* sqrt(R* delta), when
          // betas = (gamma_t/c_n) zeta sqrt(E*/(4 G*)).
          q["betan"] = pp.hertz_zeta;
          q["betas"] = mindlin && pp.g_star > 0.0
                           ? pp.shear_damping_ratio * pp.hertz_zeta * std::sqrt(pp.e_star / (4.0 * pp.g_star))
                           : 0.0;
        }
        pairs.push_back(std::move(q));
      }
    // The balls go to the driver as columns of raw little-endian numbers (balls.bin, read by the
    // driver's read_balls): a JSON list of 10^5 balls took longer to parse than the first steps.
    std::string columns;
    const auto put = [&](const auto& value) { columns.append(reinterpret_cast<const char*>(&value), sizeof value); };
    for (const auto& b : tr.balls) put(std::int64_t(b.tag));
    for (const auto& b : tr.balls) put(std::int32_t(b.type));
    for (const auto& b : tr.balls) put(std::uint8_t(b.fixed ? 1 : 0));
    for (const auto& b : tr.balls) put(b.radius);
    for (const silodem::Vec3 TranslatedBall::*v : {&TranslatedBall::x, &TranslatedBall::v, &TranslatedBall::w})
      for (const auto& b : tr.balls) columns.append(reinterpret_cast<const char*>((b.*v).data()), 3 * sizeof(double));
    nlohmann::json events = nlohmann::json::array();
    for (const auto& ev : tr.events) {
      nlohmann::json e = {{"step", ev.step},
                          {"type", ev.type},
                          {"tags", ev.tags},
                          {"velocity", {ev.velocity.x(), ev.velocity.y(), ev.velocity.z()}},
                          {"centre", {ev.centre.x(), ev.centre.y(), ev.centre.z()}},
                          {"diameter", ev.diameter},
                          {"thickness", ev.thickness}};
      if (ev.type == "insert")
        e["ball"] = {{"tag", ev.ball.tag},
                     {"type", ev.ball.type},
                     {"radius", ev.ball.radius},
                     {"fixed", false},
                     {"x", {ev.ball.x.x(), ev.ball.x.y(), ev.ball.x.z()}},
                     {"v", {ev.ball.v.x(), ev.ball.v.y(), ev.ball.v.z()}}};
      events.push_back(std::move(e));
    }
    nlohmann::json j = {{"case", cfg.name},
                              {"dt", cfg.dt},
                              {"start_step", tr.start_step},
                              {"steps", tr.steps},
                              {"events", events},
                              {"skin", tr.skin},
                              {"dump_interval", dump_interval(cfg)},
                              {"gravity", {cfg.gravity.x(), cfg.gravity.y(), cfg.gravity.z()}},
                              {"law", law_name(cfg)},
                              {"rotation", cfg.contact.rotation()},
                              {"radius_lever_arms", cfg.contact.slip_arm_radius},
                              {"types", types},
                              {"pairs", pairs},
                              {"balls_file", "balls.bin"},
                              {"ball_count", tr.balls.size()}};
    // Walls moving by a law: the driver places their balls by the same closed form.
    nlohmann::json motions = nlohmann::json::array();
    const auto vec = [](const silodem::Vec3& x) { return nlohmann::json::array({x.x(), x.y(), x.z()}); };
    for (const auto& m : tr.motions)
      motions.push_back({{"tags", m.tags},
                         {"direction", vec(m.law.direction)},
                         {"amplitude", m.law.amplitude},
                         {"frequency", m.law.frequency},
                         {"phase", m.law.phase},
                         {"centre", vec(m.law.centre)},
                         {"axis", vec(m.law.axis)},
                         {"angular_speed", m.law.angular_speed},
                         {"start_time", m.law.start_time}});
    j["motions"] = motions;
    // The planar mode (model.md §13): centres in y = 0 and spins along y, YADE's blocked degrees of
    // freedom; the grains' inertia κ m r² (the mass stays the sphere's in both codes).
    if (cfg.dimension == 2) j["planar"] = true, j["inertia_factor"] = cfg.inertia_factor;
    if (tr.outflow_below_z) j["outflow_below_z"] = *tr.outflow_below_z, j["outflow_every_steps"] = tr.outflow_every_steps;
    Input in;
    in.files = {{"case.json", j.dump(1)}, {"balls.bin", std::move(columns)}, {"yade_driver.py", kYadeDriverSource}};
    in.main_file = j.dump(1);
    in.argv = {kPython, "yade_driver.py", "case.json"};
    in.env = {std::string("PYTHONPATH=") + kYadeLib, "OMP_NUM_THREADS=1"};
    return in;
  }
};

}  // namespace

std::unique_ptr<Backend> make_yade_backend() { return std::make_unique<YadeBackend>(); }

}  // namespace harness
