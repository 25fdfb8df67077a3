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
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <fstream>

#include "harness/backends/planar_frame.hpp"
#include "harness/backends/reference_backend.hpp"
#include "harness/backends/subprocess.hpp"
#include "harness/backends/surface_mesh.hpp"
#include "silodem/contact/pair_table.hpp"

namespace harness {

namespace {

const auto fmt = full_precision;
const double kZetaMax = std::sqrt(5.0 / 6.0);  // e -> 0 in LIGGGHTS's restitution form
// LIGGGHTS's `curvature` lies between the facets' 0.5 degrees and their sharpest angle (kMeshAspect):
// edges between neighbouring facets are then flat for it, so a ball touching two facets near their edge
// is one contact, not two (with curvature below 0.5 degrees a 1 m/s impact rebounded with e 0.32, not 0.4).
const double kMeshCurvatureDegrees = 1.0;

class LiggghtsBackend final : public ReferenceBackend {
 public:
  std::string code() const override { return "liggghts"; }
  std::string set_parallel(const Parallel& p) override { return set_mpi_parallel(p); }
  std::string missing() const override {
    return find_on_path("liggghts").empty() ? "liggghts not found on PATH" : "";
  }

 protected:
  std::string code_limits(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    if (std::string why = planar_limits(cfg, tr, "LIGGGHTS", {.sphere = false, .disc = true}); !why.empty()) return why;
    if (std::string why = fix_move_limits(tr); !why.empty()) return why;
    if (!cfg.surfaces.empty() && cfg.contact.normal != silodem::NormalModel::Hertz)
      return "smooth walls (\"surfaces\") are translated for LIGGGHTS as meshes with the Hertz law only (a mesh's "
             "linear constants would come from its type, not from silodem's series pair)";
    for (const auto& s : cfg.surfaces)
      if (std::min(s.rho0, s.rho1) <= 0.0)
        return "surface \"" + s.name + "\" reaches the axis: its mesh would have triangles of no width there";
    if (!cfg.surfaces.empty() && cfg.contact.rolling != silodem::RollingModel::None)
      return "rolling resistance against smooth walls (\"surfaces\") is not translated";
    if (cfg.contact.normal == silodem::NormalModel::Hertz) {
      const auto& table = tr.pairs;
      for (std::size_t a = 0; a < table.materials(); ++a)
        for (std::size_t b = 0; b < table.materials(); ++b) {
          const auto& pp = table.at(std::int32_t(a), std::int32_t(b));
          if (!(pp.hertz_zeta < kZetaMax))
            return "a Hertz pair's damping ratio " + std::to_string(pp.hertz_zeta) + " is past what LIGGGHTS's "
                   "restitution form can give (zeta < sqrt(5/6))";
          if (cfg.contact.tangential == silodem::TangentialModel::Mindlin &&
              pp.shear_damping_ratio != (tangential_damping(table) ? own_shear_damping_ratio(pp) : 0.0))
            return "LIGGGHTS's hertz model sets its own tangential dashpot for every pair, gamma_t/gamma_n = "
                   "sqrt(S_t/S_n) = sqrt(4 G*/E*) (tangential_damping on), or none (off); a Mindlin case is "
                   "translated only if every pair's tangential_damping_ratio is 0, or every pair's is that ratio";
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

  /// LIGGGHTS's tangential dashpot of a Hertz–Mindlin pair over its normal one: 2 sqrt(5/6) beta
  /// sqrt(m* S) with S_t = 8 G* a and S_n = 2 E* a, so sqrt(4 G*/E*), rounded as silodem's cases give it.
  static double own_shear_damping_ratio(const silodem::contact::PairParams& pp) {
    const double exact = std::sqrt(4.0 * pp.g_star / pp.e_star);
    return std::abs(pp.shear_damping_ratio - exact) <= 1e-12 * exact ? pp.shear_damping_ratio : exact;
  }
  /// `tangential_damping on` when the case gives a pair a tangential dashpot (then every pair must have LIGGGHTS's).
  static bool tangential_damping(const silodem::contact::PairTable& table) {
    for (std::size_t a = 0; a < table.materials(); ++a)
      for (std::size_t b = 0; b < table.materials(); ++b)
        if (table.at(std::int32_t(a), std::int32_t(b)).shear_damping_ratio != 0.0) return true;
    return false;
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
  /// b = zeta/sqrt(5/6). Mindlin: `tangential history` with k_t = 8 G* a, and LIGGGHTS's own tangential dashpot or none.
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
         (mindlin && !tangential_damping(tr.pairs) ? " tangential_damping off" : "") + (cfg.contact.clamp ? " limitForce on" : "") + "\npair_coeff * *\n";
    return d;
  }

  /// The smooth walls as meshes (surface<k>.stl, type first_mesh_type + k) and one granular wall fix
  /// on the mobile balls with the pair style's law: R* = r and m* = m against a mesh, as silodem.
  /// A mesh's open edges touch balls as silodem's rounded rim does.
  static std::string surface_meshes(const silodem::CaseConfig& cfg, const Translation& tr, std::size_t first_mesh_type) {
    if (cfg.surfaces.empty()) return "";
    std::string d, names;
    for (std::size_t k = 0; k < cfg.surfaces.size(); ++k) {
      const std::string id = "surface" + std::to_string(k);
      d += "fix " + id + " all mesh/surface file " + id + ".stl type " + std::to_string(first_mesh_type + k) +
           " curvature " + fmt(kMeshCurvatureDegrees) + "\n";
      names += " " + id;
    }
    const bool mindlin = cfg.contact.tangential == silodem::TangentialModel::Mindlin;
    // The law's keywords follow the meshes (fix wall/gran refuses them before).
    return d + "fix surfaces mobile wall/gran model hertz tangential " + (mindlin ? "history" : "no_history") +
           " mesh n_meshes " + std::to_string(cfg.surfaces.size()) + " meshes" + names +
           (mindlin && !tangential_damping(tr.pairs) ? " tangential_damping off" : "") +
           (cfg.contact.clamp ? " limitForce on" : "") + "\n";
  }

  silodem::Mat3 frame(const silodem::CaseConfig& cfg) const override {
    return cfg.dimension == 2 ? planar_turn() : silodem::Mat3::Identity();
  }

  std::string version(const std::filesystem::path& log) const override {
    std::ifstream in(log);
    std::string l;
    while (std::getline(in, l))
      if (l.rfind("LIGGGHTS (", 0) == 0) return l;
    return "unknown";
  }

 public:
  Input write_input(const silodem::CaseConfig& cfg, const Translation& translation) const override {
    // Each smooth wall becomes a mesh (surface_mesh.hpp) whose constants LIGGGHTS reads from an atom
    // type: one more type per surface, of its material, fixed and without atoms.
    Translation tr = translation;
    // In 2-D LIGGGHTS takes a ball's density per area (m = pi r^2 rho, measured) and integrates it as a
    // disc; silodem's planar grain keeps the sphere's mass: rho' = 4/3 r rho gives it.
    if (cfg.dimension == 2) {
      for (auto& b : tr.balls) b.density *= 4.0 / 3.0 * b.radius;
      for (auto& ev : tr.events) ev.ball.density *= 4.0 / 3.0 * ev.ball.radius;
    }
    const std::size_t first_mesh_type = tr.types.size() + 1;
    for (const auto& s : cfg.surfaces) {
      tr.types.push_back(ParticleType{s.material, true, 0.0, 0.0, 0.0});
      const double rho = std::max(s.rho0, s.rho1) * 1.001;  // the mesh's vertices lie slightly outside (surface_mesh.hpp)
      for (double z : {s.z0, s.z1})
        for (double sx : {-rho, rho}) tr.box_holds.push_back({s.axis_point.x() + sx, s.axis_point.y() + sx, z});
    }
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
    d += "atom_style granular\natom_modify map array\n" + lammps_family_boundary(cfg) + "newton off\ncommunicate single vel yes\nunits si\n";
    d += decomposition(cfg) + "read_data data.lmp\n";
    if (tr.start_step > 0) d += "reset_timestep " + std::to_string(tr.start_step) + "\n";
    d += "neighbor " + fmt(tr.skin) + " bin\nneigh_modify delay 0" + groups.exclusions + "\n";
    d += cfg.contact.normal == silodem::NormalModel::Hertz ? hertz_properties(cfg, tr, matrix)
                                                           : linear_properties(cfg, tr, matrix);
    d += "timestep " + fmt(cfg.dt) + "\n";
    d += "group mobile type" + groups.mobile + "\n";
    if (!groups.wall.empty()) d += "group wall type" + groups.wall + "\n";
    d += surface_meshes(cfg, tr, first_mesh_type);
    // LIGGGHTS's dump_modify takes one format for the whole line (the default %g keeps 6 digits).
    std::string line = "dump_modify d sort id format \"%d";
    for (int i = 0; i < 11; ++i) line += " %.17g";
    line += " %g";  // v_fixed
    if (cfg.contact.rotation()) line += " %.17g %.17g %.17g";  // omegax..omegaz
    d += lammps_family_motion(cfg, tr, line + "\"", OutflowStyle::DeleteEvery);
    Input in = lammps_family_input("liggghts", "in.liggghts", d, tr);
    for (std::size_t k = 0; k < cfg.surfaces.size(); ++k)
      in.files.emplace_back("surface" + std::to_string(k) + ".stl", surface_stl(cfg.surfaces[k], kMeshSegments, kMeshAspect));
    return in;
  }
};

}  // namespace

std::unique_ptr<Backend> make_liggghts_backend() { return std::make_unique<LiggghtsBackend>(); }

}  // namespace harness
