#pragma once
// Breakage in a run (docs/model.md §14): the stage between steps that books each ended contact's
// energy on its grains (breakage/breakage_law.hpp) and replaces every grain whose accumulated
// energy reached its toughness by its fragments. The force loop reports the ended contacts and
// exempts the fragments' birth overlaps (forces/frictional_law.hpp); the run re-evaluates the
// forces after a break and books the jump in energy as breakage work (run/simulation.cpp).
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

/// Fragments are numbered from here on: beyond every listed, wall and dropped ball of any scene
/// that fits in memory.
constexpr std::int64_t kFirstFragmentTag = 1000000001;

/// One break, as breakage.csv lists it.
struct BreakRecord {
  double t = 0.0;
  std::int64_t tag = 0;
  double radius = 0.0, accumulated = 0.0, toughness = 0.0;
  int fragments = 0;
  void serialize(Archive& a);
};

/// A grain's breakage state, from its first booked contact on.
struct GrainDamage {
  double accumulated = 0.0;      // E_cum, J (34)
  double toughness = 0.0;        // E_b, J (notes B7)
  double original_radius = 0.0;  // the radius of the grain it came from (for E_min's scaling and the smallest size)
  void serialize(Archive& a);
};

class BreakageStage {
 public:
  /// `material_names`: the scene's material index order (scene/scene_builder.hpp).
  BreakageStage(const BreakageSpec& spec, std::uint64_t seed, const std::vector<std::string>& material_names);

  /// Books the contacts the accepted step ended on their breakable grains. Returns true if one is due to break.
  bool absorb(const std::vector<ContactEnd>& ended, const Particles& p);
  /// Whether contacts ending in a step that starts at t count (breakage.from_time).
  bool counts_at(double t) const { return t >= spec_.from_time; }
  /// Replaces each grain due to break by its fragments (in tag order). Returns the fragments' tags.
  std::vector<std::int64_t> break_due(Particles& p, double t);
  /// The energy a break added to the mechanical terms (booked by the run's ledger), J.
  void add_work(double work) { work_ += work; }

  nlohmann::json summary() const;
  /// <dir>/breakage.csv: one row per break.
  void write(const std::filesystem::path& dir) const;
  void serialize(Archive& a);

 private:
  bool breakable(const Particles& p, std::size_t i, const GrainDamage& g) const;
  GrainDamage& damage_of(std::int64_t tag, double radius);
  std::ptrdiff_t index_of(const Particles& p, std::int64_t tag);

  BreakageSpec spec_;
  std::uint64_t seed_;
  std::vector<std::uint8_t> breakable_material_;  // per material index
  std::map<std::int64_t, GrainDamage> damage_;    // by tag: ordered, so saved and walked alike everywhere
  std::set<std::int64_t> due_;
  std::int64_t next_tag_ = kFirstFragmentTag;
  std::vector<BreakRecord> log_;
  long fragments_ = 0;
  double work_ = 0.0;
  std::uint64_t topology_ = ~std::uint64_t(0);
  std::vector<std::pair<std::int64_t, std::size_t>> by_tag_;  // (tag, index), sorted, at topology_
};

}  // namespace silodem
