#include "silodem/forces/surface_contacts.hpp"

#include <algorithm>
#include <stdexcept>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/contact/contact_model.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/core/parallel.hpp"

namespace silodem {

void add_totals(ForceTotals& a, const ForceTotals& b) {
  a.elastic_contact += b.elastic_contact;
  a.elastic_cohesion += b.elastic_cohesion;
  a.p_dissipated += b.p_dissipated;
  a.p_cohesion += b.p_cohesion;
  a.max_overlap_ratio = std::max(a.max_overlap_ratio, b.max_overlap_ratio);
  a.contacts += b.contacts;
  a.elastic_tangential += b.elastic_tangential;
  a.elastic_rolling += b.elastic_rolling;
  a.p_friction += b.p_friction;
  a.sliding += b.sliding;
}

namespace {

/// The loop mechanics: every mobile ball against every surface, in chunks of balls whose sums are
/// added in chunk order (the same bits on any thread count). The springs are kept per ball tag and
/// surface — a ball keeps its tag through renumbering — in a committed and a trial buffer, as the
/// pair history (forces/contact_history.hpp): every evaluation reads committed and writes the
/// trial entry of every mobile ball, so commit() is a swap.
struct Load {
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
};

template <NormalModel Normal, TangentialModel Tangential, RollingModel Rolling, bool Clamp>
class SurfaceLoop final : public SurfaceContacts {
  static constexpr bool kTorques = Tangential != TangentialModel::None || Rolling != RollingModel::None;
  static constexpr bool kSpringT = Tangential == TangentialModel::LinearHistory || Tangential == TangentialModel::Mindlin;
  static constexpr bool kSpringR = Rolling == RollingModel::Spring;
  static constexpr bool kHistory = kSpringT || kSpringR;
  static constexpr int kSprings = int(kSpringT) + int(kSpringR), kColT = 0, kColR = kSprings - 1;
  using State = Eigen::Matrix<double, 3, (kSprings > 0 ? kSprings : 1)>;

 public:
  SurfaceLoop(std::vector<Surface> surfaces, contact::PairTable table, std::vector<double> k_wall,
              std::vector<double> c_wall, double dt, double slip_arm_overlap, bool rolling_limit_with_dashpot)
      : surfaces_(std::move(surfaces)), table_(std::move(table)), k_wall_(std::move(k_wall)), c_wall_(std::move(c_wall)),
        dt_(dt), slip_arm_overlap_(slip_arm_overlap), rolling_limit_with_dashpot_(rolling_limit_with_dashpot),
        loads_(surfaces_.size(), Vec3::Zero()), torques_(surfaces_.size(), Vec3::Zero()) {}

  ForceTotals compute(Particles& p) override {
    if (kTorques && !p.rotating) throw std::logic_error("frictional surface contacts on balls without rotation");
    if constexpr (kHistory) follow(p);
    const std::size_t ns = surfaces_.size(), chunks = sum_chunks(p.n_mobile);
    chunk_totals_.assign(chunks, ForceTotals{});
    chunk_loads_.assign(chunks * ns, Load{});
    SILODEM_PARALLEL_FOR
    for (long c = 0; c < long(chunks); ++c) {
      const std::size_t begin = std::size_t(c) * kSumChunk, end = std::min(begin + kSumChunk, p.n_mobile);
      for (std::size_t i = begin; i < end; ++i)
        for (std::size_t k = 0; k < ns; ++k) touch(p, i, k, chunk_totals_[std::size_t(c)], chunk_loads_[std::size_t(c) * ns + k]);
    }
    ForceTotals sum;
    std::fill(loads_.begin(), loads_.end(), Vec3::Zero());
    std::fill(torques_.begin(), torques_.end(), Vec3::Zero());
    for (std::size_t c = 0; c < chunks; ++c) {
      add_totals(sum, chunk_totals_[c]);
      for (std::size_t k = 0; k < ns; ++k) {
        loads_[k] += chunk_loads_[c * ns + k].force;
        torques_[k] += chunk_loads_[c * ns + k].torque;
      }
    }
    power_ = 0.0;
    for (std::size_t k = 0; k < ns; ++k) power_ -= surfaces_[k].angular_speed * surfaces_[k].axis.dot(torques_[k]);
    return sum;
  }

  void commit() override {
    if constexpr (kHistory) committed_.swap(trial_);
  }
  void serialize(Archive& a) override {
    a & committed_ & mobile_tag_;
    if (a.loading()) {
      if (committed_.size() != mobile_tag_.size() * surfaces_.size())
        throw CheckpointError("checkpoint payload is damaged (surface springs for another scene)");
      for (const State& s : committed_)
        if (!s.allFinite()) throw CheckpointError("checkpoint payload is damaged (a surface spring is not finite)");
      trial_ = committed_;
      topology_ = ~std::uint64_t(0);
    }
  }
  std::size_t bytes() const override {
    return heap_bytes(committed_) + heap_bytes(trial_) + heap_bytes(mobile_tag_) + heap_bytes(chunk_totals_) +
           heap_bytes(chunk_loads_);
  }
  const std::vector<Vec3>& loads() const override { return loads_; }
  const std::vector<Vec3>& torques() const override { return torques_; }
  double power() const override { return power_; }
  const std::vector<Surface>& surfaces() const override { return surfaces_; }

 private:
  /// One ball against one surface: its force and torque onto the ball, the reaction onto the load.
  void touch(Particles& p, std::size_t i, std::size_t k, ForceTotals& t, Load& load) {
    const Surface& s = surfaces_[k];
    const SurfaceGap gap = surface_gap(s, p.x[i]);
    const std::size_t h = std::size_t(p.tag[i]) * surfaces_.size() + k;
    if (gap.distance >= p.r[i]) {  // apart: a contact that ended keeps no spring
      if constexpr (kHistory) trial_[h].setZero();
      return;
    }
    contact::ContactState c;
    c.delta = p.r[i] - gap.distance;
    c.n = gap.n;  // from the wall to the centre
    // The contact point, where the ball's slip velocity is taken (contact/contact_model.hpp).
    const Vec3 x_c = p.x[i] - (p.r[i] - slip_arm_overlap_ * c.delta) * c.n;
    const bool spins = s.angular_speed != 0.0;
    c.v_rel = spins ? Vec3(p.v[i] - surface_velocity(s, x_c)) : p.v[i];
    c.delta_rate = -c.v_rel.dot(c.n);
    c.w_i = kTorques ? p.w[i] : Vec3::Zero();
    c.w_j = spins ? Vec3(s.angular_speed * s.axis) : Vec3::Zero();
    c.r_i = p.r[i];
    c.r_j = 0.0;  // unused with flat_j: R* = r_i, and the wall has no arm
    c.flat_j = true;
    c.m_eff = p.m[i];
    c.inertia_eff = p.inertia(i);
    c.inertia_contact = p.inertia(i) + p.m[i] * p.r[i] * p.r[i];
    c.k_n = contact::series(p.k[i], k_wall_[k]);  // (11), the linear law
    c.c_n = contact::series(p.c[i], c_wall_[k]);
    c.pair = &table_.at(p.material[i], s.material);
    if constexpr (kSpringT) c.spring = committed_[h].col(kColT);
    if constexpr (kSpringR) c.rolling_angle = committed_[h].col(kColR);
    c.dt = dt_;
    c.slip_arm_overlap = slip_arm_overlap_;
    c.rolling_limit_with_dashpot = rolling_limit_with_dashpot_;
    const contact::Interaction r = contact::interact<Normal, Tangential, Rolling, Clamp>(c);
    if constexpr (kSpringT) trial_[h].col(kColT) = r.spring;
    if constexpr (kSpringR) trial_[h].col(kColR) = r.rolling_angle;
    p.f[i] += r.force;
    if constexpr (kTorques) p.t[i] += r.torque_i;
    load.force -= r.force;
    // About the axis point, with the lever the ball's own torque takes (the middle of the overlap),
    // so that ball and wall exchange no net angular momentum but the rolling torques'.
    load.torque += (p.x[i] - (p.r[i] - 0.5 * c.delta) * c.n - s.centre).cross(-r.force);
    if constexpr (kTorques) load.torque += r.torque_j;
    t.add(r);
    t.max_overlap_ratio = std::max(t.max_overlap_ratio, c.delta / c.r_i);
  }

  /// After balls were added, removed, fixed or renumbered: room for every tag, and no spring left
  /// for a tag that is no longer a mobile ball (it may come back, recycled, and must start fresh).
  void follow(const Particles& p) {
    if (p.topology == topology_) return;
    topology_ = p.topology;
    std::int64_t max_tag = 0;
    for (std::size_t i = 0; i < p.n_mobile; ++i) max_tag = std::max(max_tag, p.tag[i]);
    const std::size_t ns = surfaces_.size();
    if (std::size_t(max_tag) + 1 > mobile_tag_.size()) {
      mobile_tag_.resize(std::size_t(max_tag) + 1, 0);
      committed_.resize(mobile_tag_.size() * ns, State::Zero());
      trial_.resize(mobile_tag_.size() * ns, State::Zero());
    }
    std::vector<char> now(mobile_tag_.size(), 0);
    for (std::size_t i = 0; i < p.n_mobile; ++i) now[std::size_t(p.tag[i])] = 1;
    for (std::size_t tag = 0; tag < now.size(); ++tag)
      if (mobile_tag_[tag] && !now[tag])
        for (std::size_t k = 0; k < ns; ++k) committed_[tag * ns + k].setZero(), trial_[tag * ns + k].setZero();
    mobile_tag_.swap(now);
  }

  std::vector<Surface> surfaces_;
  contact::PairTable table_;
  std::vector<double> k_wall_, c_wall_;  // the surfaces' materials' per-ball k_i, c_i (linear law)
  double dt_, slip_arm_overlap_;
  bool rolling_limit_with_dashpot_;
  std::vector<Vec3> loads_, torques_;
  double power_ = 0.0;
  std::vector<State> committed_, trial_;  // by tag × surface
  std::vector<char> mobile_tag_;          // by tag: a mobile ball at the last topology
  std::uint64_t topology_ = ~std::uint64_t(0);
  std::vector<ForceTotals> chunk_totals_;
  std::vector<Load> chunk_loads_;
};

struct Build {
  std::vector<Surface> surfaces;
  const CaseConfig& cfg;
  std::vector<double> k, c;
  template <NormalModel N, TangentialModel T, RollingModel R, bool Clamp>
  std::unique_ptr<SurfaceContacts> make() {
    return std::make_unique<SurfaceLoop<N, T, R, Clamp>>(std::move(surfaces), contact::pair_table(cfg), k, c, cfg.dt,
                                                         cfg.contact.slip_arm_radius ? 0.0 : 0.5,
                                                         cfg.contact.rolling_limit_with_dashpot);
  }
  template <NormalModel N, TangentialModel T, RollingModel R>
  std::unique_ptr<SurfaceContacts> clamp() {
    return cfg.contact.clamp ? make<N, T, R, true>() : make<N, T, R, false>();
  }
  template <NormalModel N, TangentialModel T>
  std::unique_ptr<SurfaceContacts> rolling() {
    switch (cfg.contact.rolling) {
      case RollingModel::ConstantTorque: return clamp<N, T, RollingModel::ConstantTorque>();
      case RollingModel::Spring: return clamp<N, T, RollingModel::Spring>();
      case RollingModel::None: break;
    }
    return clamp<N, T, RollingModel::None>();
  }
  template <NormalModel N>
  std::unique_ptr<SurfaceContacts> tangential() {
    switch (cfg.contact.tangential) {
      case TangentialModel::None: return rolling<N, TangentialModel::None>();
      case TangentialModel::CoulombSliding: return rolling<N, TangentialModel::CoulombSliding>();
      case TangentialModel::LinearHistory: return rolling<N, TangentialModel::LinearHistory>();
      case TangentialModel::Mindlin:
        if constexpr (N == NormalModel::Hertz) return rolling<N, TangentialModel::Mindlin>();
        break;
    }
    throw std::logic_error("no such tangential law with this normal law");
  }
};

}  // namespace

std::unique_ptr<SurfaceContacts> make_surface_contacts(const CaseConfig& cfg,
                                                       const std::vector<std::string>& material_names) {
  if (cfg.surfaces.empty()) return nullptr;
  if (cfg.contact.cohesion || cfg.contact.onset_correction)
    throw std::invalid_argument("smooth walls take no cohesion and no onset correction");
  Build b{{}, cfg, {}, {}};
  for (const SurfaceSpec& s : cfg.surfaces) {
    const auto at = std::find(material_names.begin(), material_names.end(), s.material);
    if (at == material_names.end()) throw std::logic_error("surface material not in the scene: " + s.material);
    b.surfaces.push_back(surface_from(s, std::int32_t(at - material_names.begin())));
    b.k.push_back(cfg.materials.at(s.material).k);
    b.c.push_back(cfg.materials.at(s.material).c);
  }
  if (cfg.contact.normal == NormalModel::Hertz) return b.tangential<NormalModel::Hertz>();
  return b.tangential<NormalModel::Linear>();
}

}  // namespace silodem
