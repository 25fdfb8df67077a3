// LAMMPS (Debian `lammps`, 29 Sep 2021): the only file that knows LAMMPS.
// Mapping (facts verified in docs/reference-codes.md, Measured facts: LAMMPS):
//  - Kelvin–Voigt with constant k, c: `pair_style granular`, `hooke k c ... damping velocity`
//    (force k δ + c δ̇, c in N s/m, not mass-scaled). Mixing is geometric by default, so every
//    type pair gets an explicit pair_coeff with the series values (11).
//  - frictionless: `tangential linear_nohistory 0 0`.
//  - friction (docs/reference-codes.md, sub-models by code): the history spring as `tangential
//    linear_history k_t x_gamma mu` (k_t = rho k_ij, x_gamma = gamma_t/c_ij, the same increment, rotation
//    of the spring into the tangent plane and reset at the cap); the seeds' sliding law as `tangential
//    linear_nohistory x_gamma mu` (gamma_t = x_gamma c_ij); one pair_coeff per type pair carries the
//    pair's own mu (grain–wall differs from grain–grain). Rotation by the same fix nve/sphere.
//  - rolling: the EPSD spring as `rolling sds` (k_roll = k_r/R*^2, gamma_roll = C_r/R*^2); LAMMPS caps
//    spring and dashpot together where silodem caps the spring and drops the dashpot at the limit.
//    No constant directional torque in this version.
//  - clamp: `limit_damping` (LAMMPS's default does not clamp, like the paper).
//  - wall balls: own types, not integrated, gravity on the mobile group only, wall–wall pairs
//    excluded from the neighbour list; the wall load is their per-atom force.
//  - integration: fix nve/sphere — velocity Verlet, the dashpot sees the half-step velocity.
//  - stages: gate balls deleted by id, leavers by `fix evaporate` in the region below the outflow
//    height, closure by taking the slab's mobile balls out of the integrated group.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

#include "harness/backends/planar_frame.hpp"
#include "harness/backends/reference_backend.hpp"
#include "harness/backends/subprocess.hpp"
#include "silodem/contact/pair_constants.hpp"

namespace harness {

namespace {

const auto fmt = full_precision;

/// LAMMPS's Tsuji polynomial alpha(e) (pair granular, `damping tsuji`), decreasing from 1.2728 at e = 0.
double tsuji_polynomial(double e) {
  return 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * std::pow(e, 3) + 27.467 * std::pow(e, 4) -
         18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
}
constexpr double kTsujiAlphaMax = 1.2728, kTsujiAlphaMin = 0.0003;
double tsuji_alpha(double zeta) { return 2.0 * zeta * std::sqrt(1.5); }
/// The e that LAMMPS turns into alpha (bisection on [0, 1], to the last bit).
double tsuji_restitution(double alpha) {
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 200 && hi - lo > 0.0; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (tsuji_polynomial(mid) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

class LammpsBackend final : public ReferenceBackend {
 public:
  std::string code() const override { return "lammps"; }
  std::string set_parallel(const Parallel& p) override { return set_mpi_parallel(p); }
  std::string missing() const override { return find_on_path("lmp").empty() ? "lmp not found on PATH" : ""; }

 protected:
  std::string code_limits(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    if (std::string why = planar_limits(cfg, tr, "LAMMPS", {.sphere = true, .disc = true}); !why.empty()) return why;
    if (std::string why = fix_move_limits(tr); !why.empty()) return why;
    for (const auto& s : cfg.surfaces)
      if (s.z0 == s.z1)
        return "surface \"" + s.name + "\" is a flat ring: LAMMPS's region walls have no bounded flat ring (a plane is infinite)";
    if (!cfg.surfaces.empty() && cfg.contact.rolling != silodem::RollingModel::None)
      return "rolling resistance against smooth walls is not translated for LAMMPS";
    if (cfg.contact.normal == silodem::NormalModel::Hertz) {
      const auto& table = tr.pairs;
      for (std::size_t a = 0; a < table.materials(); ++a)
        for (std::size_t b = 0; b < table.materials(); ++b)
          if (const double alpha = tsuji_alpha(table.at(std::int32_t(a), std::int32_t(b)).hertz_zeta);
              alpha > kTsujiAlphaMax || (alpha > 0.0 && alpha < kTsujiAlphaMin))
            return "a Hertz pair's damping ratio is outside what LAMMPS's damping tsuji can express (its alpha from "
                   "0.0003 at e = 1 to 1.2728 at e = 0; this pair needs " + std::to_string(alpha) + ")";
    }
    if (cfg.contact.rolling == silodem::RollingModel::ConstantTorque)
      return "LAMMPS 29Sep2021 has no constant directional rolling torque (its one rolling model, rolling sds, is a "
             "spring-dashpot-slider)";
    if (cfg.contact.rolling == silodem::RollingModel::Spring) {
      if (cfg.contact.normal == silodem::NormalModel::Hertz)
        return "rolling sds takes one k_roll per type pair; silodem's EPSD k_r = 2.25 k_n mu_r^2 R*^2 follows the Hertz "
               "stiffness, which grows with the overlap";
      for (std::size_t a = 1; a <= tr.types.size(); ++a)
        for (std::size_t b = a; b <= tr.types.size(); ++b) {
          if (!(tr.pair(int(a), int(b)).rolling_damping_ratio > 0.0)) continue;
          if (!cfg.contact.rolling_limit_with_dashpot)
            return "rolling sds holds spring and dashpot together at its limit, silodem's EPSD by default the spring alone "
                   "(the same only without a rolling dashpot): contact.rolling_limit \"spring_and_dashpot\" runs LAMMPS's form";
          if (tr.type_radii(int(a)).size() > 1 || tr.type_radii(int(b)).size() > 1)
            return "rolling sds takes one gamma_roll per type pair; silodem's EPSD dashpot C_r/R*^2 depends on the radii, "
                   "and types " + std::to_string(a) + ", " + std::to_string(b) + " hold more than one";
        }
    }
    if (cfg.contact.tangential == silodem::TangentialModel::CoulombSliding) {
      const auto& table = tr.pairs;
      for (const auto& [a, ma] : cfg.materials)
        for (const auto& [b, mb] : cfg.materials)
          if (silodem::contact::series(ma.c, mb.c) == 0.0 && table.at(a, b).sliding_damping > 0.0)
            return "the sliding law's gamma_t of materials " + a + " and " + b + " has no LAMMPS form: linear_nohistory "
                   "scales the normal dashpot c_ij, which is 0 for this pair";
    }
    return "";
  }

  /// The normal model of the pair_coeff for types a, b. Hertz: `hertz/material E damp nu` makes
  /// E* = E/(2(1 - nu^2)) from one pair's E and nu, so E = 2 E* with nu = 0; `damping tsuji` gives
  /// c = alpha sqrt(m* 4/3 E* a), silodem c = 2 zeta sqrt(2 m* E* a) (model.md §10.3), so alpha = 2 zeta sqrt(3/2),
  /// and LAMMPS takes the restitution whose Tsuji polynomial is that alpha.
  static std::string normal(const silodem::CaseConfig& cfg, const silodem::contact::PairParams& pp, double k, double c) {
    if (cfg.contact.normal == silodem::NormalModel::Linear) return "hooke " + fmt(k) + " " + fmt(c);
    if (pp.hertz_zeta == 0.0) return "hertz/material " + fmt(2.0 * pp.e_star) + " 0 0";  // no dashpot: damping velocity 0
    return "hertz/material " + fmt(2.0 * pp.e_star) + " " + fmt(tsuji_restitution(tsuji_alpha(pp.hertz_zeta))) + " 0";
  }
  static std::string damping(const silodem::CaseConfig& cfg, const silodem::contact::PairParams& pp) {
    const bool tsuji = cfg.contact.normal == silodem::NormalModel::Hertz && pp.hertz_zeta > 0.0;
    return tsuji ? " damping tsuji" : " damping velocity";
  }

  /// The tangential model of the pair_coeff for types a, b: the solver's constants (translation.hpp).
  static std::string tangential(const silodem::CaseConfig& cfg, const silodem::contact::PairParams& pp, double k, double c) {
    switch (cfg.contact.tangential) {
      case silodem::TangentialModel::LinearHistory:
        return " tangential linear_history " + fmt(pp.shear_ratio * k) + " " + fmt(pp.shear_damping_ratio) +
               " " + fmt(pp.friction);
      case silodem::TangentialModel::Mindlin:  // k_t = 8 G* a: LAMMPS multiplies the given 8 G* by a
        return " tangential mindlin " + fmt(8.0 * pp.g_star) + " " + fmt(pp.shear_damping_ratio) + " " + fmt(pp.friction);
      case silodem::TangentialModel::CoulombSliding: {
        return " tangential linear_nohistory " + fmt(c > 0.0 ? pp.sliding_damping / c : 0.0) + " " + fmt(pp.friction);
      }
      default: return " tangential linear_nohistory 0 0";
    }
  }

  /// The rolling model of the pair_coeff for types a, b: `rolling sds k_roll gamma_roll mu_roll`
  /// pushes a displacement psi += R* (w_rel x n) dt with force -k_roll psi - gamma_roll R* (w_rel x n)
  /// and torque R* n x F, i.e. silodem's EPSD torque with k_roll = k_r/R*^2 = 2.25 k_ij mu_r^2 and
  /// gamma_roll = C_r/R*^2, C_r from the pair's one radius per type (code_limits checks there is one).
  static std::string rolling(const silodem::CaseConfig& cfg, const Translation& tr, int a, int b) {
    if (cfg.contact.rolling != silodem::RollingModel::Spring) return "";
    const auto& pp = tr.pair(a, b);
    const double k_roll = 2.25 * tr.pair_k(a, b) * pp.rolling_friction * pp.rolling_friction;
    double gamma_roll = 0.0;
    if (pp.rolling_damping_ratio > 0.0) {
      const TranslatedBall *bi = tr.ball_of_type(a), *bj = tr.ball_of_type(b);
      if (bi && bj && !(bi->fixed && bj->fixed)) {  // wall–wall pairs are never computed
        const double r_i = bi->radius, r_j = bj->radius, r_star = r_i * r_j / (r_i + r_j);
        // About the contact point I + m r^2 = 1.4 m r^2 per ball in series; a wall ball adds nothing.
        const auto contact_inertia = [](const TranslatedBall& x) {
          return x.fixed ? INFINITY : 1.4 * x.mass * x.radius * x.radius;
        };
        const double inertia = 1.0 / (1.0 / contact_inertia(*bi) + 1.0 / contact_inertia(*bj));
        const double k_r = k_roll * r_star * r_star;
        gamma_roll = 2.0 * pp.rolling_damping_ratio * std::sqrt(inertia * k_r) / (r_star * r_star);
      }
    }
    return " rolling sds " + fmt(k_roll) + " " + fmt(gamma_roll) + " " + fmt(pp.rolling_friction);
  }

  /// Smooth walls (docs/model.md §11) as region walls: a vertical segment a `cylinder`, a sloped one
  /// a `cone`, both with open ends (their surface alone), `side in`. One `fix wall/gran/region` per
  /// surface and mobile type, with the pair constants of the type's material and the surface's.
  /// LAMMPS takes R* = r and m* = m against a wall, as silodem does. Unlike silodem's rounded rim, a
  /// region wall does not touch a ball whose centre is past an open end (docs/reference-codes.md).
  static std::string surface_walls(const silodem::CaseConfig& cfg, const Translation& tr) {
    std::string d;
    for (std::size_t k = 0; k < cfg.surfaces.size(); ++k) {
      const silodem::SurfaceSpec& s = cfg.surfaces[k];
      const bool up = s.z1 > s.z0;
      const double r_lo = up ? s.rho0 : s.rho1, r_hi = up ? s.rho1 : s.rho0;
      const std::string axis = " z " + fmt(s.axis_point.x()) + " " + fmt(s.axis_point.y()) + " ";
      const std::string span = " " + fmt(std::min(s.z0, s.z1)) + " " + fmt(std::max(s.z0, s.z1));
      d += "region surface" + std::to_string(k) +
           (s.rho0 == s.rho1 ? " cylinder" + axis + fmt(s.rho0) : " cone" + axis + fmt(r_lo) + " " + fmt(r_hi)) + span +
           " side in open 1 open 2 units box\n";
    }
    for (std::size_t t = 1; t <= tr.types.size(); ++t) {
      const ParticleType& type = tr.types[t - 1];
      if (type.fixed || tr.type_count(int(t)) == 0) continue;
      const std::string group = "surface_type" + std::to_string(t);
      d += "group " + group + " type " + std::to_string(t) + "\n";
      for (std::size_t k = 0; k < cfg.surfaces.size(); ++k) {
        const silodem::Material& wall = cfg.materials.at(cfg.surfaces[k].material);
        const auto& pp = tr.pairs.at(type.material, wall.name);
        const double kk = silodem::contact::series(type.k, wall.k), c = silodem::contact::series(type.c, wall.c);
        d += "fix surface" + std::to_string(k) + "_" + std::to_string(t) + " " + group + " wall/gran/region granular " +
             normal(cfg, pp, kk, c) + tangential(cfg, pp, kk, c) + damping(cfg, pp) +
             (cfg.contact.clamp ? " limit_damping" : "") + " region surface" + std::to_string(k) + "\n";
      }
    }
    return d;
  }

  silodem::Mat3 frame(const silodem::CaseConfig& cfg) const override {
    return cfg.dimension == 2 ? planar_turn() : silodem::Mat3::Identity();
  }

  std::string version(const std::filesystem::path& log) const override {
    std::ifstream in(log);
    std::string l;
    while (std::getline(in, l))
      if (l.rfind("LAMMPS (", 0) == 0) return l;
    return "unknown";
  }

 public:
  Input write_input(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    const TypeGroups groups = lammps_type_groups(tr);
    std::string d;
    d += "# silodem case \"" + cfg.name + "\" translated for LAMMPS\n";
    d += "units si\natom_style sphere\natom_modify map array\n" + lammps_family_boundary(cfg) + "newton off\ncomm_modify vel yes\n";
    d += decomposition(cfg) + "read_data data.lmp\n";
    if (tr.start_step > 0) d += "reset_timestep " + std::to_string(tr.start_step) + "\n";
    d += "group mobile type" + groups.mobile + "\n";
    if (!groups.wall.empty()) d += "group wall type" + groups.wall + "\n";
    d += "pair_style granular\n";
    for (std::size_t a = 1; a <= tr.types.size(); ++a)
      for (std::size_t b = a; b <= tr.types.size(); ++b) {
        const int ia = int(a), ib = int(b);
        const auto& pp = tr.pair(ia, ib);
        const double k = tr.pair_k(ia, ib), c = tr.pair_c(ia, ib);
        d += "pair_coeff " + std::to_string(a) + " " + std::to_string(b) + " " + normal(cfg, pp, k, c) +
             tangential(cfg, pp, k, c) + rolling(cfg, tr, ia, ib) + damping(cfg, pp) +
             (cfg.contact.clamp ? " limit_damping" : "") + "\n";
      }
    d += "neighbor " + fmt(tr.skin) + " bin\nneigh_modify delay 0 every 1 check yes" + groups.exclusions + "\n";
    d += "timestep " + fmt(cfg.dt) + "\n";
    d += surface_walls(cfg, tr);
    // A planar grain is a disc or a sphere (planar_limits refuses other inertias).
    const bool disc = cfg.dimension == 2 && cfg.inertia_factor == 0.5;
    d += lammps_family_motion(cfg, tr, "dump_modify d sort id format float %.17g", OutflowStyle::Evaporate,
                              disc ? "nve/sphere disc" : "nve/sphere");
    return lammps_family_input("lmp", "in.lammps", d, tr);
  }
};

}  // namespace

std::unique_ptr<Backend> make_lammps_backend() { return std::make_unique<LammpsBackend>(); }

}  // namespace harness
