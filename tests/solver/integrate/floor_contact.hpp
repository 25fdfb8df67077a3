#pragma once
// One ball resting on a fixed "floor" ball under gravity, at its static overlap, through the real
// frictional force loop (make_force_field) and a real integrator: the tangential and rotational
// dynamics of one contact as a run steps them (the run loop's step, then commit). The floor is a
// ball of radius 1000 m, as in tests/references/friction_test.cpp: over the micrometres the ball
// moves here its surface departs from a plane by under 10⁻¹² m.
#include <memory>

#include "silodem/forces/force_field.hpp"
#include "silodem/integrate/integrator.hpp"
#include "silodem/integrate/predictor_corrector.hpp"
#include "silodem/integrate/velocity_verlet.hpp"

namespace silodem::floor_test {

struct FloorSpec {
  TangentialModel law = TangentialModel::LinearHistory;
  double r = 0.01, m = 4e-3, g = 9.81;  // ball: m, kg, m/s²
  double k_n = 1e5, c_n = 0.0;          // pair constants (each ball carries twice them, (11))
  double shear_ratio = 2.0 / 7.0, shear_damping_ratio = 0.0;  // k_t = ρ k_n, γ_t = ρ_γ c_n
  double sliding_damping = 0.0;         // γ_t of the sliding law
  double mu = 1e6;                      // large: the contact never reaches the Coulomb cap
};

class FloorContact {
 public:
  static constexpr double kFloorRadius = 1000.0;

  FloorContact(const FloorContact&) = delete;  // eval captures this
  FloorContact& operator=(const FloorContact&) = delete;
  FloorContact(const FloorSpec& s, double dt) : s_(s) {
    Material grain;
    grain.name = "grain";
    grain.k = 2.0 * s.k_n;
    grain.c = 2.0 * s.c_n;
    grain.friction = s.mu;
    grain.shear_stiffness_ratio = s.shear_ratio;
    grain.tangential_damping_ratio = s.shear_damping_ratio;
    grain.tangential_damping = 2.0 * s.sliding_damping;
    CaseConfig cfg;
    cfg.materials["grain"] = grain;
    cfg.contact.tangential = s.law;
    cfg.gravity = Vec3(0, 0, -s.g);
    cfg.dt = dt;
    field_ = make_force_field(cfg);
    const double z = kFloorRadius + s.r - static_overlap();
    p.add({Vec3(0, 0, z), Vec3::Zero(), s.r, s.m, grain.k, grain.c, 0, "ball", 1}, false);
    p.add({Vec3::Zero(), Vec3::Zero(), kFloorRadius, 1.0, grain.k, grain.c, 0, "floor", 2}, true);
    p.enable_rotation();
    list_.build(p);
    eval = [this](Particles& q) {
      list_.update(q);
      return field_->compute(q, list_);
    };
  }

  double static_overlap() const { return s_.m * s_.g / s_.k_n; }
  /// Lever arm from the centre to the contact point (r − δ/2, docs/model.md §10.1).
  double arm() const { return s_.r - 0.5 * static_overlap(); }
  double inertia() const { return 0.4 * s_.m * s_.r * s_.r; }
  /// Effective mass of the slip: d(v − aω)/dt = F (1/m + a²/I), m_t = 2/7 m for a = r.
  double slip_mass() const { return 1.0 / (1.0 / s_.m + arm() * arm() / inertia()); }
  /// Starts a slip s0 along x with no angular momentum about the contact point (m a v + I ω = 0):
  /// only the slip mode moves, and the ball does not roll away.
  void start_slip_mode(double s0) {
    p.v[0] = Vec3(slip_mass() / s_.m * s0, 0, 0);
    p.w[0] = Vec3(0, -arm() * slip_mass() / inertia() * s0, 0);
  }
  /// Slip of the ball's surface over the floor along x: v − a ω_y (n = +z).
  double slip() const { return p.v[0].x() - arm() * p.w[0].y(); }

  /// Energy of the tangential motion: kinetic (translation along the floor and spin) and spring.
  double slip_energy(const ForceTotals& t) const {
    return 0.5 * s_.m * p.v[0].head<2>().squaredNorm() + 0.5 * inertia() * p.w[0].squaredNorm() + t.elastic_tangential;
  }
  /// Height of the centre above its resting height, m.
  double lift() const { return p.x[0].z() - (kFloorRadius + s_.r - static_overlap()); }

  /// One step as the run loop takes it: the integrator, then the accepted history.
  StepReport step(Integrator& in, double dt) {
    const StepReport r = in.step(p, eval, dt);
    field_->commit();
    return r;
  }

  Particles p;
  ForceEvaluation eval;

 private:
  FloorSpec s_;
  NeighbourList list_{0.1 * 0.01, 0.0};
  std::unique_ptr<ForceField> field_;
};

/// The schemes of the order and stability tests. ε = 0: every corrector pass is taken.
inline std::unique_ptr<Integrator> make_scheme(const IntegratorSpec& s, const Vec3& g) {
  if (s.scheme == Scheme::VelocityVerlet) return std::make_unique<VelocityVerlet>(g, s.half_step_dashpot);
  return std::make_unique<PredictorCorrector>(g, s.max_corrector_passes, CorrectorStop::FixedPoint, 0.0);
}

/// A sticking spring for the tangential stability runs: ρ = 2 puts the normal mode at ω_t/2.65,
/// inside its own limit over the whole search; ζ_n = 0.01, and ρ_γ sets ζ_t = γ_t/(2√(k_t m_t)).
inline FloorSpec sticking_spec(double zeta_t) {
  FloorSpec s;
  s.shear_ratio = 2.0;
  s.c_n = 2.0 * 0.01 * std::sqrt(s.k_n * s.m);
  FloorContact c(s, 1e-6);
  s.shear_damping_ratio = zeta_t * 2.0 * std::sqrt(s.shear_ratio * s.k_n * c.slip_mass()) / s.c_n;
  return s;
}

}  // namespace silodem::floor_test
