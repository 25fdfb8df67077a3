#pragma once
// The energy ledger (docs/theory.md §8.1): kinetic + gravitational + elastic (contact and cohesion
// springs) + dashpot dissipation + cohesion-exit losses must equal the initial total plus the
// energy brought in by drops. Powers are integrated with the trapezoidal rule, so the residual
// measures the integrator's own error, and anything beyond it is a bug.
#include <nlohmann/json.hpp>

#include "silodem/forces/force_field.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

struct EnergyState {
  double t = 0.0;
  double kinetic = 0.0;
  double gravitational = 0.0;  // −Σ m g·x, datum x = 0
  double elastic = 0.0;        // contact + cohesion springs
  double dissipated = 0.0;     // ∫ dashpot power dt (and an integrator's artificial viscosity's)
  double cohesion_removed = 0.0;  // energy carried off by cohesion springs that let go
  double injected = 0.0;       // energy brought in: balls added by drops (kinetic + gravitational at
                               // insertion) and the work of moving walls on the grains
  double withdrawn = 0.0;      // energy of mobile balls taken out (discharged, or stopped and fixed)
  double initial = 0.0;        // total at t = 0
  double balance = 0.0;        // Σ terms − initial − injected + withdrawn (0 for an exact integrator)
  double scale = 0.0;          // energy that has moved through the mechanical terms (drift denominator)
  // Friction and rotation (zero in a frictionless scene; kinetic and elastic above include them).
  double rotational = 0.0;          // Σ ½ I ω², part of kinetic
  double elastic_tangential = 0.0;  // tangential springs, part of elastic
  double elastic_rolling = 0.0;     // rolling springs (EPSD), part of elastic
  double friction_dissipated = 0.0; // ∫ friction power dt − tangential and rolling spring energy:
                                    // lost to sliding, tangential and rolling dashpots, rolling plasticity
  double relative_drift() const { return scale > 0.0 ? balance / scale : 0.0; }
};

class EnergyLedger {
 public:
  /// `with_friction`: the scene has friction or rotation (its checkpoint then holds those terms).
  explicit EnergyLedger(const Vec3& gravity, bool with_friction = false) : g_(gravity), with_friction_(with_friction) {}

  /// First state; sets the initial total.
  void start(const Particles& p, const ForceTotals& t, double time);
  /// A state one step of length dt after the previous record.
  void record(const Particles& p, const ForceTotals& t, double time, double dt);
  /// A ball entered the system (a drop) carrying kinetic and gravitational energy.
  void inject(double m, const Vec3& x, const Vec3& v);
  /// A mobile ball left the system (removed, or stopped and turned into a wall ball).
  void withdraw(double m, const Vec3& x, const Vec3& v);
  /// Ball i of p leaves: its translational, rotational and gravitational energy.
  void withdraw_ball(const Particles& p, std::size_t i);
  /// Work done on the grains by moving walls during a step (motion/wall_motion.hpp).
  void add_wall_work(double work) { s_.injected += work; }
  /// Grains broke between steps (breakage/breakage_stage.hpp) and `t` holds the forces evaluated
  /// after it: the jump of the state's terms (the fragments' kinetic energy against the parent's,
  /// the vanished springs of its contacts) is booked as energy brought in. Returns the jump, J.
  double book_breakage(const Particles& p, const ForceTotals& t);
  /// Energy an integrator's artificial viscosity took out during a step (integrate/runge_kutta_midpoint.hpp).
  void add_viscous_work(double work) { s_.dissipated += work; }

  const EnergyState& state() const { return s_; }
  double max_abs_relative_drift() const { return max_drift_; }
  void serialize(Archive& a);
  /// The ledger as it goes into a result summary ("energy").
  nlohmann::json summary() const;

 private:
  void totals(const Particles& p, const ForceTotals& t);
  Vec3 g_;
  bool with_friction_;
  EnergyState s_;
  double p_diss_prev_ = 0.0, p_coh_prev_ = 0.0, cohesion_inflow_ = 0.0;
  double p_friction_prev_ = 0.0, friction_work_ = 0.0;  // ∫ friction power dt
  double mechanical_max_ = 0.0, max_drift_ = 0.0;
  std::vector<double> chunk_sums_;  // scratch: kinetic and gravitational energy per chunk of balls
};

}  // namespace silodem
