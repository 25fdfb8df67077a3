#pragma once
// The stages of a silo run after filling (docs/model.md §7, Algorithm 5 remarks): discharge — the balls
// closing the outlet become mobile, balls that leave are recycled as drops at the top or removed —
// and sudden gate closure — mobile balls in the outlet plane are stopped and become wall balls —
// and walls set moving at a prescribed velocity (a piston, a shear box; motion/wall_motion.hpp).
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/energy/energy_ledger.hpp"
#include "silodem/fill/drop_feeder.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

/// One ball that left through the outlet.
struct ExitRecord {
  double t = 0.0;
  std::string id;
  double mass = 0.0;
  Vec3 x = Vec3::Zero();  // where it left (a tray's slots are told apart by it)
  void serialize(Archive& a);
};

class StageController {
 public:
  StageController(const CaseConfig& cfg, EnergyLedger& ledger);

  /// Applies events that are due and takes out balls below the outflow height. Returns true if the
  /// ball set changed (the integrator must then re-evaluate forces).
  bool apply(Particles& p, long step, double t, DropFeeder* feeder);
  /// Exits since the last call (for the outflow probe).
  std::vector<ExitRecord> take_exits() { return std::move(exits_); }
  std::size_t converted() const { return converted_; }
  /// Checkpoint: which events are done and the closure count (exits are taken every step).
  void serialize(Archive& a);

 private:
  const CaseConfig& cfg_;
  EnergyLedger& ledger_;
  std::vector<bool> done_;
  bool replayed_ = false;  // the move_wall events before a continuation's start set again
  std::vector<ExitRecord> exits_;
  std::size_t converted_ = 0;
};

}  // namespace silodem
