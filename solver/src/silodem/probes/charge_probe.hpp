#pragma once
// Charge probe: the mobile balls of a vessel as one body — a mill's charge. Its mass, centre of
// mass, angular momentum about the turning wall's axis, and the volume Σ (4/3)π r³ of its grains
// (which breakage keeps). Over a window from `from_time`, the mean centre of mass and the angular
// momentum at the window's two ends: with the wall's mean torque (wall_load probe) they give the
// torque identity ⟨T⟩ = M (⟨x̄⟩ − c) × g − ΔL/τ of a charge in a turning drum (docs/model.md §12).
// A row every `interval` seconds.
#include <vector>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/probes/probe.hpp"

namespace silodem {

/// One sample of the charge (a namespace-scope type: clang rejects a nested type's default member
/// initialisers used inside the enclosing class).
struct ChargeSample {
  double t = 0.0, mass = 0.0, volume = 0.0;
  long balls = 0;
  Vec3 centre_of_mass = Vec3::Zero(), angular_momentum = Vec3::Zero();
  double kinetic = 0.0;
  void serialize(Archive& a) { a & t & mass & volume & balls & centre_of_mass & angular_momentum & kinetic; }
};

class ChargeProbe final : public Probe {
 public:
  /// About the turning wall's axis point (its motion law's centre), or its centre if it does not turn.
  ChargeProbe(const ProbeSpec& spec, const WallSpec& wall);
  void sample(const Particles& p, double t) override;
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  ChargeSample measure(const Particles& p, double t) const;
  ProbeSpec spec_;
  Vec3 centre_;
  ChargeSample first_, last_, window_start_;
  Vec3 com_sum_ = Vec3::Zero();
  double mass_sum_ = 0.0;
  long samples_ = 0, window_samples_ = 0;
  double next_row_ = 0.0;
  std::vector<ChargeSample> rows_;
};

}  // namespace silodem
