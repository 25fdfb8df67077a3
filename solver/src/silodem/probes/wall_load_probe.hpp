#pragma once
// Wall load probe: the resultant force and torque the balls exert on one wall (of balls, or a
// smooth surface), and the power the wall puts into them — a mill's torque and power draw, a
// tray's drive force. Torque about the
// wall's rotation centre if it turns (motion/motion_law.hpp), else about the wall's own centre:
//   F = Σ f_w,   T = Σ (x_w − c) × f_w + t_w,   P = −Σ (f_w·v_w + t_w·ω_w)
// over the wall's balls w (f_w, t_w: the contact force and torque on w). A row every `interval`
// seconds, and the time means from `from_time` (to `to_time` if given).
#include <vector>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/probes/probe.hpp"

namespace silodem {

// One sample of a wall's load (a namespace-scope type: clang rejects a nested type's default
// member initialisers used inside the enclosing class, as std::pair<double, Load> does).
struct WallLoad {
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double power = 0.0;
  void serialize(Archive& a) { a & force & torque & power; }
};

class SurfaceContacts;

class WallLoadProbe final : public Probe {
 public:
  WallLoadProbe(const ProbeSpec& spec, const WallSpec& wall);
  /// On a smooth wall (every segment of the case's surface `spec.wall`), torque about its axis
  /// point, from the surface contacts' last evaluation (forces/surface_contacts.hpp).
  WallLoadProbe(const ProbeSpec& spec, const SurfaceContacts& surfaces);
  void sample(const Particles& p, double t) override;
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  using Load = WallLoad;
  Load measure(const Particles& p);
  ProbeSpec spec_;
  std::string wall_;
  Vec3 centre_;
  std::uint64_t topology_ = ~std::uint64_t(0);
  std::vector<std::size_t> index_;  // the wall's balls, or the surface's segments
  const SurfaceContacts* surfaces_ = nullptr;  // set for a smooth wall
  Load sum_, last_;
  double torque_max_ = 0.0;  // largest |T| in the window (the bound of its mean's end terms)
  long samples_ = 0;
  double next_row_ = 0.0;
  std::vector<std::pair<double, Load>> rows_;
};

}  // namespace silodem
