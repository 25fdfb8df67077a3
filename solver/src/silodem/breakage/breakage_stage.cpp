#include "silodem/breakage/breakage_stage.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "silodem/breakage/breakage_law.hpp"
#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

namespace silodem {

void BreakRecord::serialize(Archive& a) { a & t & tag & radius & accumulated & toughness & fragments; }
void GrainDamage::serialize(Archive& a) { a & accumulated & toughness & original_radius; }

BreakageStage::BreakageStage(const BreakageSpec& spec, std::uint64_t seed, const std::vector<std::string>& material_names)
    : spec_(spec), seed_(seed), breakable_material_(material_names.size(), 0) {
  for (std::size_t k = 0; k < material_names.size(); ++k)
    breakable_material_[k] = std::uint8_t(std::count(spec.materials.begin(), spec.materials.end(), material_names[k]) > 0);
}

std::ptrdiff_t BreakageStage::index_of(const Particles& p, std::int64_t tag) {
  if (p.topology != topology_ || by_tag_.size() != p.size()) {
    by_tag_.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) by_tag_[i] = {p.tag[i], i};
    std::sort(by_tag_.begin(), by_tag_.end());
    topology_ = p.topology;
  }
  const auto it = std::lower_bound(by_tag_.begin(), by_tag_.end(), std::make_pair(tag, std::size_t(0)));
  return it != by_tag_.end() && it->first == tag ? std::ptrdiff_t(it->second) : -1;
}

GrainDamage& BreakageStage::damage_of(std::int64_t tag, double radius) {
  auto [it, fresh] = damage_.try_emplace(tag);
  if (fresh) it->second = {0.0, breakage::toughness(seed_, tag, spec_.strength), radius};
  return it->second;
}

bool BreakageStage::breakable(const Particles& p, std::size_t i, const GrainDamage& g) const {
  return i < p.n_mobile && breakable_material_[std::size_t(p.material[i])] &&
         p.r[i] >= spec_.smallest_ratio * g.original_radius * (1.0 - 1e-12);
}

bool BreakageStage::absorb(const std::vector<ContactEnd>& ended, const Particles& p) {
  for (const ContactEnd& e : ended) {
    const std::ptrdiff_t a = index_of(p, e.tag_i), b = index_of(p, e.tag_j);
    if (a < 0 || b < 0) continue;  // a ball that left (never a grain still here)
    const bool with_wall = std::size_t(a) >= p.n_mobile || std::size_t(b) >= p.n_mobile;
    if (with_wall && !spec_.wall_contacts) continue;
    for (const std::ptrdiff_t i : {a, b}) {
      const std::size_t k = std::size_t(i);
      if (k >= p.n_mobile || !breakable_material_[std::size_t(p.material[k])]) continue;
      GrainDamage& g = damage_of(p.tag[k], p.r[k]);
      if (!breakable(p, k, g)) continue;
      g.accumulated += breakage::energy_increment(e.energy, spec_.minimum_energy, p.r[k], g.original_radius, spec_.size_exponent);
      if (g.accumulated >= g.toughness) due_.insert(p.tag[k]);
    }
  }
  return !due_.empty();
}

std::vector<std::int64_t> BreakageStage::break_due(Particles& p, double t) {
  std::vector<std::int64_t> born;
  if (due_.empty()) return born;
  // In tag order, the fragments and their tags; then the parents leave, highest index first (a
  // removal moves only balls above it); then the fragments join.
  std::vector<std::size_t> parents;
  std::vector<Particles::Ball> joining;
  for (const std::int64_t tag : due_) {
    const std::ptrdiff_t found = index_of(p, tag);
    if (found < 0) continue;
    const std::size_t i = std::size_t(found);
    const Particles::Ball parent = p.ball(i);
    const GrainDamage g = damage_.at(tag);
    const int n = breakage::fragment_count(seed_, tag, spec_.count_mean, spec_.count_sd, spec_.count_min, spec_.count_max);
    // The ring lies in the x–z plane: the planar mode's plane, and one fixed choice in 3-D.
    for (const auto& f : breakage::fragments(parent.x, parent.v, parent.w, parent.r, n, Vec3::UnitY(), Vec3::UnitX())) {
      Particles::Ball b = parent;
      b.x = f.x, b.v = f.v, b.w = p.rotating ? f.w : Vec3::Zero(), b.r = f.r, b.m = parent.m / double(n);
      b.tag = next_tag_++;
      b.id = "fragment" + std::to_string(b.tag - kFirstFragmentTag + 1);
      damage_.emplace(b.tag, GrainDamage{0.0, breakage::toughness(seed_, b.tag, spec_.strength), g.original_radius});
      born.push_back(b.tag);
      joining.push_back(std::move(b));
    }
    parents.push_back(i);
    log_.push_back({t, tag, parent.r, g.accumulated, g.toughness, n});
    fragments_ += n;
    damage_.erase(tag);
  }
  std::sort(parents.rbegin(), parents.rend());
  for (const std::size_t i : parents) p.remove_mobile(i);
  p.reserve(p.size() + joining.size());
  for (const auto& b : joining) p.add(b, false);
  due_.clear();
  return born;
}

nlohmann::json BreakageStage::summary() const {
  return {{"breaks", log_.size()}, {"fragments", fragments_}, {"work", work_}, {"file", "breakage.csv"}};
}

void BreakageStage::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(12) << "t,tag,radius,accumulated_energy,toughness,fragments\n";
  for (const BreakRecord& b : log_)
    out << b.t << ',' << b.tag << ',' << b.radius << ',' << b.accumulated << ',' << b.toughness << ',' << b.fragments << '\n';
  write_file_checked(dir / "breakage.csv", out.str());
}

void BreakageStage::serialize(Archive& a) {
  std::vector<std::pair<std::int64_t, GrainDamage>> flat(damage_.begin(), damage_.end());
  std::vector<std::int64_t> due(due_.begin(), due_.end());
  a & flat & due & next_tag_ & log_ & fragments_ & work_;
  if (a.loading()) {
    damage_ = std::map<std::int64_t, GrainDamage>(flat.begin(), flat.end());
    due_ = std::set<std::int64_t>(due.begin(), due.end());
    topology_ = ~std::uint64_t(0);
  }
}

}  // namespace silodem
