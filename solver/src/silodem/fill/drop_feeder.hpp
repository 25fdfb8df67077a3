#pragma once
// Filling (Algorithm 2 and Algorithm 5 line 10): while balls remain and the fill is below the
// release height, place a new ball at its analytic first contact.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/core/random.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

struct DropRecord {
  long index = 0;              // drop number, 0-based; −1 for a recycled ball
  std::string recycled_id;     // the recycled ball's id ("" for a new drop)
  double t = 0.0;
  Vec3 start = Vec3::Zero();   // release centre (x0, y0, z0)
  double r = 0.0;
  std::string outcome;         // "placed", "no_obstacle" (rejected: outside the silo), "start_overlaps"
  double h = 0.0;              // fall height to the first contact
  std::string obstacle_id;     // id of the ball touched
  long obstacle_index = -1;
  Vec3 x = Vec3::Zero(), v = Vec3::Zero();  // placed state (16)
  void serialize(Archive& a);
};

class DropFeeder {
 public:
  /// Drop k gets the dump tag first_tag + k.
  DropFeeder(const DropSpec& spec, const Material& material, std::int32_t material_index, const Vec3& gravity,
             std::uint64_t seed, std::int64_t first_tag);
  /// One attempt if it is due (every interval_steps steps, fill height below z0, balls left).
  /// Recycled balls go first, keeping their id, tag and radius.
  std::optional<DropRecord> maybe_drop(Particles& p, long step, double t);
  /// Placement "release" (DropSpec::release): the drops still to come, in order — index, release
  /// point (start = x), initial velocity v and radius, as the run will draw them. Attempt k is made at step
  /// k·interval_steps. What the translation hands every reference code.
  std::vector<DropRecord> planned_releases() const;
  /// A ball that left through the outlet, to be dropped again at the top (docs/model.md §7.2).
  void recycle(const Particles::Ball& b) { recycled_.push_back(b); }
  std::size_t waiting() const { return recycled_.size(); }
  bool done() const { return full_ || attempted_ >= spec_.count; }
  /// The fill reached full_level (the count was not needed); time it did, NaN if not.
  bool full() const { return full_; }
  double full_time() const { return full_time_; }
  long placed() const { return placed_; }
  long rejected() const { return attempted_ - placed_; }

  /// Checkpoint: the random engine, the recycled queue and the counters.
  void serialize(Archive& a);
  /// Fill height: the median over columns (side 4 r_max) of the inlet of the highest mobile centre.
  double surface_height(const Particles& p) const;

 private:
  Vec3 draw_start();     // (14), or the next explicit point
  double draw_radius();  // (1)
  std::optional<DropRecord> release(Particles& p, double t);
  void add_new(Particles& p, const DropRecord& rec);

  DropSpec spec_;
  Material material_;
  std::int32_t material_index_;
  double g_abs_;
  Random rng_;
  std::int64_t first_tag_;
  std::vector<Particles::Ball> recycled_;
  long attempted_ = 0, placed_ = 0;
  bool full_ = false;
  double full_time_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace silodem
