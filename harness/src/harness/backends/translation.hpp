#pragma once
// What every reference backend starts from: the case's balls in dump-tag order, with the
// constants the solver derived, each (material, fixed) kind as one particle type, the series pair
// constants (11) for every pair of types, and the analytic drops done up front. One translation,
// so all codes receive the same numbers.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/contact/pair_table.hpp"
#include "silodem/fill/drop_feeder.hpp"
#include "silodem/motion/motion_law.hpp"

namespace harness {

struct TranslatedBall {
  std::int64_t tag = 0;    // 1-based, as in every dump
  std::string id;
  int type = 0;            // 1-based particle type
  double radius = 0.0, density = 0.0, mass = 0.0;
  bool fixed = false;
  silodem::Vec3 x = silodem::Vec3::Zero(), v = silodem::Vec3::Zero();
  silodem::Vec3 w = silodem::Vec3::Zero();  // angular velocity
};

struct ParticleType {
  std::string material;
  bool fixed = false;
  double k = 0.0, c = 0.0, density = 0.0;  // per-ball constants
};

/// A stage event as a reference code applies it: at the top of step `step` (before that step's
/// integration), as run/stages.cpp does.
struct TranslatedEvent {
  long step = 0;
  std::string type;                 // "open_outlet" (its balls are deleted), "close_outlet", "insert" or "move_wall"
  std::vector<std::int64_t> tags;   // open_outlet, move_wall: the wall's balls
  silodem::Vec3 centre = silodem::Vec3::Zero();
  double diameter = 0.0, thickness = 0.0;  // close_outlet: the slab whose mobile balls are stopped and fixed
  TranslatedBall ball;              // insert: a released drop at its release point and velocity
  // move_wall: the balls' velocity from this step on; `motion` names the moving set (one group and
  // fix per wall in LAMMPS), `moved_before` says an earlier event of this run set it moving.
  silodem::Vec3 velocity = silodem::Vec3::Zero();
  std::string motion;
  bool moved_before = false;
};

/// The shortest leaver-deletion interval translated (reference_backend.hpp: OutflowStyle).
/// A wall in prescribed motion (its case's "motion" law), from the first step: its balls and the law.
struct TranslatedMotion {
  std::string wall;                 // the case's name of the wall
  std::string group;                // a name for the code's group of its balls
  std::vector<std::int64_t> tags;   // the wall's balls
  silodem::MotionLaw law;
};

constexpr long kMinOutflowEvery = 10;

struct Translation {
  std::vector<TranslatedBall> balls;
  std::vector<ParticleType> types;             // index = type − 1
  std::vector<silodem::DropRecord> drops;      // analytic placements made before the first step
  long start_step = 0;                         // a continuation starts here (dumps count from it)
  long steps = 0;                              // the step the run ends at (absolute)
  std::vector<TranslatedEvent> events;         // those still to come, in time order
  std::vector<TranslatedMotion> motions;       // walls moving by a law (one harmonic translation or one turn each)
  std::optional<double> outflow_below_z;       // mobile balls whose centre falls below are deleted
  long outflow_every_steps = 1;                // at every step s with s % this == 0 (stages.outflow.every_steps)
  double skin = 0.0;
  /// Multiplies the density of wall balls in the LAMMPS/LIGGGHTS data file. Their mass enters those
  /// codes only through the effective mass m* of a wall pair, which silodem takes as the mobile
  /// ball's; the Hertz dashpot reads m*, and LIGGGHTS's EPSD rolling dashpot the wall ball's m r², so
  /// a Hertz or EPSD case gives wall balls 1e12 times their density (m* = m_i to 1e-12). 1 otherwise.
  double wall_density_factor = 1.0;
  silodem::contact::PairTable pairs;          // the solver's constants per material pair (docs/model.md §10.4)
  /// Points the LAMMPS-family box must hold besides the balls (a mesh's corners: LIGGGHTS refuses a
  /// mesh outside the box).
  std::vector<silodem::Vec3> box_holds;
  /// The code's axes: x_code = frame x_silodem for every vector above (planar_frame.hpp turns a planar
  /// case for LAMMPS and LIGGGHTS); the dump is turned back by its transpose.
  silodem::Mat3 frame = silodem::Mat3::Identity();
  /// Whether the code runs in turned axes (a planar case in a LAMMPS-family code's 2-D mode).
  bool turned() const { return !frame.isIdentity(); }
  /// k_ij, c_ij for types a, b (1-based), series (11).
  double pair_k(int a, int b) const;
  double pair_c(int a, int b) const;
  /// Friction, rolling and Hertz constants of types a, b (1-based), as the solver combines them.
  const silodem::contact::PairParams& pair(int a, int b) const;
  /// The radii the balls of a type (1-based) have, initial balls and inserted ones.
  std::set<double> type_radii(int type) const;
  /// How many balls of the type a run has (initial and inserted).
  std::size_t type_count(int type) const;
  /// A ball of the type (initial or inserted), or none.
  const TranslatedBall* ball_of_type(int type) const;
  /// Whether balls of types a and b can ever touch: not two walls, and not a type with a single ball with itself.
  bool can_touch(int a, int b) const;
};

/// Empty `reason` means representable. Drops placed at their analytic first contact (Algorithm 2)
/// depend on the packing at the drop, which reference codes can only reproduce before the first
/// step: such a case with more than one drop is not representable by them. Released drops
/// (placement "release") are: each becomes an "insert" event at its step. Stages: outlet opening by taking the
/// gate away, outflow by removal and sudden closure are translated; recycling leavers as analytic
/// drops and setting overlapping gate balls free are not.
Translation translate(const silodem::CaseConfig& cfg, std::string& reason);

/// The neighbour skin the solver would use (so every code uses the same).
double case_skin(const silodem::CaseConfig& cfg);

}  // namespace harness
