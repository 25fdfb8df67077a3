// LIGGGHTS-PUBLIC 3.8.0 (Debian `liggghts`): the only file that knows LIGGGHTS.
// Mapping (docs/reference-codes.md, Measured facts: LIGGGHTS):
//  - Kelvin–Voigt with constant k, c: `pair_style gran model hooke/stiffness tangential no_history
//    absolute_damping on`; the full type-pair matrices kn and gamman_abs carry the series values (11).
//  - frictionless: kt = 0, gammat_abs = 0, coefficientFriction = 0.
//  - the history spring: `tangential history` with the matrices kt = rho k_ij, gammat_abs = rho_gamma c_ij,
//    coefficientFriction = mu_ij (docs/reference-codes.md, sub-models by code). LIGGGHTS caps the spring
//    alone and adds the dashpot on top while the spring is below the cap (silodem and LAMMPS cap the sum).
//  - rolling: `rolling_friction cdt` (the constant torque, without silodem's one-step limit, from the
//    elastic normal force) and `epsd` (the EPSD spring, linear law only: not rotated with the contact).
//  - clamp: `limitForce on` (off by default, like the paper).
//  - wall balls: own types, not integrated, gravity on mobile only, wall–wall pairs excluded.
//  - integration: fix nve/sphere (velocity Verlet, dashpot at the half-step velocity).
//  - stages: as LAMMPS, but leavers are deleted by delete_atoms between run segments of stages.outflow.every_steps (no fix evaporate).
#include <cmath>
#include <cstdio>
#include <numbers>
#include <fstream>

#include "harness/backends/reference_backend.hpp"
#include "harness/backends/subprocess.hpp"
#include "silodem/contact/pair_table.hpp"

namespace harness {

namespace {

const auto fmt = full_precision;
const double kZetaMax = std::sqrt(5.0 / 6.0);  // e -> 0 in LIGGGHTS's restitution form

class LiggghtsBackend final : public ReferenceBackend {
 public:
  std::string code() const override { return "liggghts"; }
  std::string missing() const override {
    return find_on_path("liggghts").empty() ? "liggghts not found on PATH" : "";
  }

 protected:
  std::string code_limits(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    if (!cfg.surfaces.empty()) return "smooth walls (\"surfaces\") are not translated for LIGGGHTS yet (LAMMPS takes them as region walls)";
    if (cfg.contact.normal == silodem::NormalModel::Hertz) {
      const auto& table = tr.pairs;
      for (std::size_t a = 0; a < table.materials(); ++a)
        for (std::size_t b = 0; b < table.materials(); ++b) {
          const auto& pp = table.at(std::int32_t(a), std::int32_t(b));
          if (!(pp.hertz_zeta < kZetaMax))
            return "a Hertz pair's damping ratio " + std::to_string(pp.hertz_zeta) + " is past what LIGGGHTS's "
                   "restitution form can give (zeta < sqrt(5/6))";
          if (cfg.contact.tangential == silodem::TangentialModel::Mindlin && pp.shear_damping_ratio != 0.0)
            return "LIGGGHTS's hertz model sets its own tangential dashpot (2 sqrt(5/6) beta sqrt(m* k_t)) or none "
                   "(tangential_damping off); a Mindlin case with tangential_damping_ratio > 0 is not translated";
        }
    }
    if (cfg.contact.rolling != silodem::RollingModel::None && cfg.contact.tangential != silodem::TangentialModel::LinearHistory &&
        cfg.contact.tangential != silodem::TangentialModel::Mindlin)
      return "LIGGGHTS 3.8 keeps its rolling state in the tangential history: rolling resistance needs tangential history";
    if (cfg.contact.rolling_limit_with_dashpot)
      for (std::size_t a = 1; a <= tr.types.size(); ++a)
        for (std::size_t b = 1; b <= tr.types.size(); ++b)
          if (tr.pair(int(a), int(b)).rolling_damping_ratio > 0.0)
            return "LIGGGHTS's epsd holds the spring alone at its limit and drops the dashpot there; contact.rolling_limit "
                   "\"spring_and_dashpot\" (LAMMPS's form) has no LIGGGHTS form";
    if (cfg.contact.rolling == silodem::RollingModel::Spring && cfg.contact.normal == silodem::NormalModel::Hertz)
      return "LIGGGHTS's epsd takes k_n as its hertz model's secant stiffness (2/3 of the tangent silodem's EPSD uses)";
    if (cfg.contact.tangential == silodem::TangentialModel::CoulombSliding)
      return "LIGGGHTS 3.8 has no sliding Coulomb law without a spring (tangential no_history is frictionless)";
    if (cfg.contact.slip_arm_radius)
      return "LIGGGHTS 3.8 takes the slip velocity at the contact point (lever arm r - delta/2); contact.slip_lever_arm "
             "\"radius\" has no LIGGGHTS form";
    return "";
  }

  /// The rolling model: `rolling_friction cdt` (mu_r R* times the elastic normal force, no one-step
  /// limit) or `epsd` (k_r = 2.25 k_n mu_r^2 R*^2, dashpot eta_r 2 sqrt(I_r k_r), I_r from I + m r^2 of
  /// both balls: the wall balls' mass is scaled up, Translation::wall_density_factor), mu_r and eta_r per
  /// type pair. The pair_style keyword, and the matrices it reads.
  template <class Matrix>
  static std::string rolling_properties(const silodem::CaseConfig& cfg, const Translation& tr, const Matrix& matrix) {
    if (cfg.contact.rolling == silodem::RollingModel::None) return "";
    std::string d = matrix("coefficientRollingFriction", [&](int a, int b) { return tr.pair(a, b).rolling_friction; });
    if (cfg.contact.rolling == silodem::RollingModel::Spring)
      d += matrix("coefficientRollingViscousDamping", [&](int a, int b) { return tr.pair(a, b).rolling_damping_ratio; });
    return d;
  }
  static std::string rolling_keyword(const silodem::CaseConfig& cfg) {
    switch (cfg.contact.rolling) {
      case silodem::RollingModel::ConstantTorque: return " rolling_friction cdt";
      case silodem::RollingModel::Spring: return " rolling_friction epsd";
      default: return "";
    }
  }

  /// The paper's linear law: full type-pair matrices of k_ij, c_ij; the history spring
  /// (tangential history) with k_t = rho k_ij, gamma_t = rho_gamma c_ij and mu per type pair.
  template <class Matrix>
  static std::string linear_properties(const silodem::CaseConfig& cfg, const Translation& tr, const Matrix& matrix) {
    std::string d = matrix("kn", [&](int a, int b) { return tr.pair_k(a, b); });
    const bool history = cfg.contact.tangential == silodem::TangentialModel::LinearHistory;
    d += matrix("kt", [&](int a, int b) { return history ? tr.pair(a, b).shear_ratio * tr.pair_k(a, b) : 0.0; });
    d += matrix("gamman_abs", [&](int a, int b) { return tr.pair_c(a, b); });
    d += matrix("gammat_abs", [&](int a, int b) { return history ? tr.pair(a, b).shear_damping_ratio * tr.pair_c(a, b) : 0.0; });
    d += matrix("coefficientFriction", [&](int a, int b) { return history ? tr.pair(a, b).friction : 0.0; });
    d += rolling_properties(cfg, tr, matrix);
    d += std::string("pair_style gran model hooke/stiffness tangential ") + (history ? "history" : "no_history") +
         rolling_keyword(cfg) + " absolute_damping on" +
         (cfg.contact.clamp ? " limitForce on" : "") + "\npair_coeff * *\n";
    return d;
  }

  /// The Hertz law: per-type E and nu (LIGGGHTS combines 1/E* = sum (1 - nu^2)/E and G* as silodem
  /// does), and per type pair the restitution whose damping 2 sqrt(5/6) (-beta) sqrt(m* S_n),
  /// beta = ln e / sqrt(ln^2 e + pi^2), is silodem's c = 2 zeta sqrt(m* S_n): e = exp(-pi b/sqrt(1 - b^2)),
  /// b = zeta/sqrt(5/6). Mindlin: `tangential history` with k_t = 8 G* a and no tangential dashpot.
  template <class Matrix>
  static std::string hertz_properties(const silodem::CaseConfig& cfg, const Translation& tr, const Matrix& matrix) {
    auto per_type = [&](const std::string& name, auto value) {
      std::string s = "fix m_" + name + " all property/global " + name + " peratomtype";
      for (const auto& t : tr.types) s += " " + fmt(value(cfg.materials.at(t.material)));
      return s + "\n";
    };
    // LIGGGHTS refuses E > 1e9 Pa in SI units unless told the particles are hard.
    std::string d = "hard_particles yes\n";
    d += per_type("youngsModulus", [](const silodem::Material& m) { return m.youngs_modulus; });
    d += per_type("poissonsRatio", [](const silodem::Material& m) { return m.poisson_ratio; });
    d += matrix("coefficientRestitution", [&](int a, int b) {
      const double beta = tr.pair(a, b).hertz_zeta / std::sqrt(5.0 / 6.0);
      return std::exp(-std::numbers::pi * beta / std::sqrt(1.0 - beta * beta));
    });
    const bool mindlin = cfg.contact.tangential == silodem::TangentialModel::Mindlin;
    d += matrix("coefficientFriction", [&](int a, int b) { return mindlin ? tr.pair(a, b).friction : 0.0; });
    d += rolling_properties(cfg, tr, matrix);
    d += std::string("pair_style gran model hertz tangential ") + (mindlin ? "history" : "no_history") + rolling_keyword(cfg) +
         (mindlin ? " tangential_damping off" : "") + (cfg.contact.clamp ? " limitForce on" : "") + "\npair_coeff * *\n";
    return d;
  }

  std::string version(const std::filesystem::path& log) const override {
    std::ifstream in(log);
    std::string l;
    while (std::getline(in, l))
      if (l.rfind("LIGGGHTS (", 0) == 0) return l;
    return "unknown";
  }

 public:
  Input write_input(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    const std::size_t n = tr.types.size();
    auto matrix = [&](const std::string& name, auto value) {
      std::string s = "fix m_" + name + " all property/global " + name + " peratomtypepair " + std::to_string(n);
      for (std::size_t a = 1; a <= n; ++a)
        for (std::size_t b = 1; b <= n; ++b) s += " " + fmt(value(int(a), int(b)));
      return s + "\n";
    };
    const TypeGroups groups = lammps_type_groups(tr);
    std::string d;
    d += "# silodem case \"" + cfg.name + "\" translated for LIGGGHTS\n";
    d += "atom_style granular\natom_modify map array\nboundary m m m\nnewton off\ncommunicate single vel yes\nunits si\n";
    d += "read_data data.lmp\n";
    if (tr.start_step > 0) d += "reset_timestep " + std::to_string(tr.start_step) + "\n";
    d += "neighbor " + fmt(tr.skin) + " bin\nneigh_modify delay 0" + groups.exclusions + "\n";
    d += cfg.contact.normal == silodem::NormalModel::Hertz ? hertz_properties(cfg, tr, matrix)
                                                           : linear_properties(cfg, tr, matrix);
    d += "timestep " + fmt(cfg.dt) + "\n";
    d += "group mobile type" + groups.mobile + "\n";
    if (!groups.wall.empty()) d += "group wall type" + groups.wall + "\n";
    // LIGGGHTS's dump_modify takes one format for the whole line (the default %g keeps 6 digits).
    std::string line = "dump_modify d sort id format \"%d";
    for (int i = 0; i < 11; ++i) line += " %.17g";
    line += " %g";  // v_fixed
    if (cfg.contact.rotation()) line += " %.17g %.17g %.17g";  // omegax..omegaz
    d += lammps_family_motion(cfg, tr, line + "\"", OutflowStyle::DeleteEvery);
    return lammps_family_input("liggghts", "in.liggghts", d, tr);
  }
};

}  // namespace

std::unique_ptr<Backend> make_liggghts_backend() { return std::make_unique<LiggghtsBackend>(); }

}  // namespace harness
