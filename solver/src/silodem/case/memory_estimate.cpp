#include "silodem/case/memory_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "silodem/case/case_error.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/core/available_memory.hpp"
#include "silodem/fill/drop_feeder.hpp"
#include "silodem/run/stages.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

using nlohmann::json;

namespace {

// Sizes of what the solver holds, from its own types so that they follow the code.
// Particles: x, v, f, r, m, k, c, material, id, tag (scene/particles.hpp).
constexpr double kBallArrays = 3 * sizeof(Vec3) + 4 * sizeof(double) + sizeof(std::int32_t) + sizeof(std::string) +
                               sizeof(std::int64_t);
// Neighbour list per ball: reverse offsets and fill, cell and cell slot, up to 4 cells per ball
// (start and fill) (neighbour/neighbour_list.cpp); per mobile ball: offsets, position at the build.
constexpr double kListPerBall = 2 * sizeof(std::size_t) + 2 * sizeof(std::uint32_t) + 4 * 2 * sizeof(std::uint32_t);
constexpr double kListPerMobile = sizeof(std::size_t) + sizeof(Vec3);
// Per listed pair: slot, owner, reverse slot, chunk buffer; with threads the wall-slot force and
// its mark (forces/pair_loop.hpp). Doubled: these arrays grow by resize, so capacity runs ahead.
constexpr double kPairBytes = 2.0 * (4 * sizeof(std::uint32_t) + sizeof(Vec3) + sizeof(std::uint32_t));
// Friction, rotation or Hertz (forces/frictional_field.cpp): per slot, with threads, the torque of
// a wall slot (forces/pair_loop.hpp), and the history store's two springs and two tags
// (forces/contact_history.hpp), doubled as above; per ball ω and the torque, and the integrators'
// ω arrays.
constexpr double kFrictionPairBytes = 2.0 * (sizeof(Vec3) + 2 * sizeof(Vec3) + 2 * sizeof(std::int64_t));
constexpr double kRotationBallBytes = 2 * sizeof(Vec3);
constexpr double kRollingSpringPairBytes = 2.0 * 2 * sizeof(Vec3);  // the EPSD spring's two buffers
// A dense random packing with the default skin lists 4.5 pairs per mobile ball
// (reports/bench_scaling.md); at least 6 are counted.
constexpr double kPairsPerBallMin = 6.0;
constexpr double kDensestPacking = 0.7405;  // π/√18

/// What malloc takes for a request of n bytes (glibc: 8 bytes of header, 16-byte chunks, 32 at least).
double malloc_bytes(double n) { return std::max(32.0, std::ceil((n + 8.0) / 16.0) * 16.0); }

/// Heap bytes of a std::string's text beyond its small-string buffer.
double string_heap(const std::string& s) { return s.size() > 15 ? malloc_bytes(double(s.size() + 1)) : 0.0; }

/// One ball of state.json as written (output/state_file.cpp): its text (numbers at full precision)
/// in the one string the file is built in, which grows by doubling (up to twice the text), and its
/// sort slot.
double state_ball_bytes(bool fixed) {
  const double x = -0.0012855814492372091;
  json b = {{"id", "drop1000000"}, {"material", "material"}, {"radius", x}, {"position", {x, x, x}}};
  b[fixed ? "fixed" : "velocity"] = fixed ? json(true) : json({x, x, x});
  return 2.0 * double(b.dump().size() + 2) + sizeof(std::size_t);
}

/// The cohesion reach |δ_c| = p_N g m_max / k_ij bound (forces/force_field.cpp, max_cohesion_reach).
double cohesion_reach(const CaseConfig& cfg, double r_max) {
  if (!cfg.contact.cohesion) return 0.0;
  double rho_max = 0.0, k_min = INFINITY;
  for (const auto& [name, m] : cfg.materials) rho_max = std::max(rho_max, m.density), k_min = std::min(k_min, m.k);
  return cfg.contact.p_n * cfg.gravity.norm() * rho_max * 4.0 / 3.0 * kPi * std::pow(r_max, 3) / (0.5 * k_min);
}

/// Listed pairs per mobile ball: the balls of the densest packing whose centres lie within the
/// list distance of the smallest ball, half of them (each pair is stored once), at least 6.
double pairs_per_mobile(const CaseConfig& cfg) {
  double r_lo = INFINITY, r_hi = 0.0, r_any = 0.0;
  for (const auto& b : cfg.balls) {
    r_any = std::max(r_any, b.radius);
    if (!b.fixed) r_lo = std::min(r_lo, b.radius), r_hi = std::max(r_hi, b.radius);
  }
  if (cfg.drops) r_lo = std::min(r_lo, cfg.drops->r_min), r_hi = std::max(r_hi, cfg.drops->r_max);
  if (!std::isfinite(r_lo)) return 0.0;
  const double skin = cfg.skin > 0.0 ? cfg.skin : 0.2 * r_lo;  // run/simulation.cpp, default_skin
  const double reach = std::min(cohesion_reach(cfg, std::max(r_hi, r_any)), 10.0 * r_hi);
  const double d = (r_lo + r_hi + skin + reach) / r_lo;
  return std::max(kPairsPerBallMin, 0.5 * kDensestPacking * d * d * d);
}

struct BallCosts {
  double fixed, mobile;
};

BallCosts ball_costs(const CaseConfig& cfg) {
  const bool rotating = cfg.contact.rotation();
  // Vec3 arrays per ball (translation, spin): Verlet ü; predictor–corrector five; midpoint ü, x0, v0, v½ and α, ω0.
  const double per_ball = cfg.integrator.scheme == Scheme::VelocityVerlet        ? (rotating ? 4.0 : 2.0)
                          : cfg.integrator.scheme == Scheme::RungeKuttaMidpoint ? (rotating ? 6.0 : 4.0)
                                                                                 : (rotating ? 10.0 : 5.0);
  const double integrator = per_ball * double(sizeof(Vec3));
  const double pairs = pairs_per_mobile(cfg);
  const double pair_bytes = kPairBytes + (cfg.contact.frictionless_linear() ? 0.0 : kFrictionPairBytes) +
                            (cfg.contact.rolling == RollingModel::Spring ? kRollingSpringPairBytes : 0.0);
  const double rotation = rotating ? kRotationBallBytes : 0.0;
  // A checkpoint is serialised whole in memory before it is written: the ball arrays and the list.
  const double checkpoint = cfg.checkpoint.enabled() ? kBallArrays + 8.0 * pairs : 0.0;
  // The final state: state.sds is streamed (a sort slot per ball); state.json once more as text.
  const double state_fixed = cfg.state_json ? state_ball_bytes(true) : sizeof(std::size_t);
  const double state_mobile = cfg.state_json ? state_ball_bytes(false) : sizeof(std::size_t);
  const double fixed = kBallArrays + rotation + kListPerBall + state_fixed + checkpoint;
  // Integrator arrays grow with the drops by resize: room for twice the balls.
  return {fixed, kBallArrays + rotation + kListPerBall + kListPerMobile + 2.0 * integrator + pairs * pair_bytes +
                     state_mobile + checkpoint};
}

/// A listed or wall ball as the case holds it (BallSpec, in a vector grown by push_back: room for
/// twice), and its id once more in the scene.
double spec_bytes(const BallSpec& b) { return 2.0 * sizeof(BallSpec) + 2.0 * string_heap(b.id) + string_heap(b.material); }

std::string count_text(double n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, n < 1e7 ? "%.0f" : "%.3g", n);
  return buf;
}

void add_ball_terms(const CaseConfig& cfg, const BallCosts& cost, MemoryEstimate& e) {
  const json* listed = cfg.source.is_object() && cfg.source.contains("balls") ? &cfg.source["balls"] : nullptr;
  const std::size_t n_listed = std::min(cfg.listed_balls, cfg.balls.size());
  double bytes = listed ? 2.0 * json_heap_bytes(*listed) : 0.0;  // the case's copy and the summary's
  for (std::size_t i = 0; i < n_listed; ++i)
    bytes += spec_bytes(cfg.balls[i]) + (cfg.balls[i].fixed ? cost.fixed : cost.mobile);
  if (n_listed > 0) e.terms.push_back({count_text(double(n_listed)) + " listed balls", "$.balls", bytes});
  // Generated grains come last (case/generate_keys.cpp).
  const std::size_t n_generated = std::min(cfg.generated_balls, cfg.balls.size() - n_listed);
  double generated = 0.0;
  for (std::size_t i = cfg.balls.size() - n_generated; i < cfg.balls.size(); ++i)
    generated += spec_bytes(cfg.balls[i]) + cost.mobile;
  if (n_generated > 0) e.terms.push_back({count_text(double(n_generated)) + " generated grains", "$.generate", generated});
  // Wall balls follow the listed ones, wall by wall, as ids <name>_<n> (scene/wall_builders.cpp).
  std::size_t at = n_listed;
  for (std::size_t w = 0; w < cfg.walls.size(); ++w) {
    const std::string prefix = cfg.walls[w].name + "_";
    double wall_bytes = 0.0, n = 0.0;
    for (; at < cfg.balls.size() && cfg.balls[at].id.rfind(prefix, 0) == 0; ++at, ++n) {
      wall_bytes += spec_bytes(cfg.balls[at]) + cost.fixed;
      for (const auto& p : cfg.probes)  // a pressure probe's index, cell, normal and tangent per ball
        if (p.type == "wall_pressure" && p.wall == cfg.walls[w].name)
          wall_bytes += 2 * sizeof(std::size_t) + 2 * sizeof(Vec3);
    }
    e.terms.push_back({count_text(n) + " balls of wall \"" + cfg.walls[w].name + "\"",
                       "$.walls[" + std::to_string(w) + "].spacing", wall_bytes});
  }
}

void add_drop_terms(const CaseConfig& cfg, const BallCosts& cost, MemoryEstimate& e) {
  if (!cfg.drops) return;
  const DropSpec& d = *cfg.drops;
  bool drops_probe = false, outflow_probe = false;
  for (const auto& p : cfg.probes) drops_probe |= p.type == "drops", outflow_probe |= p.type == "outflow";
  double per_drop = cost.mobile;
  if (drops_probe) per_drop += 2.0 * sizeof(DropRecord);  // one record per attempt, in a growing vector
  if (cfg.outflow.enabled && cfg.outflow.recycle) per_drop += 2.0 * sizeof(Particles::Ball);  // waiting to be re-dropped
  if (outflow_probe) per_drop += 2.0 * sizeof(ExitRecord);
  e.terms.push_back({count_text(double(d.count)) + " drops", "$.drops.count", double(d.count) * per_drop});
  if (d.positions.empty()) {
    // The fill height's grid of columns of side 4 r_max over the inlet (fill/drop_feeder.cpp).
    const double side = 4.0 * d.r_max;
    const double columns = std::max(1.0, std::ceil((d.x_max - d.x_min) / side)) *
                           std::max(1.0, std::ceil((d.y_max - d.y_min) / side));
    e.terms.push_back({count_text(columns) + " fill-height columns over the inlet (side 4 r_max)", "$.drops.inlet",
                       columns * sizeof(double)});
  }
}

void add_probe_terms(const CaseConfig& cfg, MemoryEstimate& e) {
  const double steps = std::ceil(cfg.duration / cfg.dt);
  for (std::size_t k = 0; k < cfg.probes.size(); ++k) {
    const ProbeSpec& p = cfg.probes[k];
    const std::string path = "$.output.probes[" + std::to_string(k) + "]";
    if (p.type == "section_force") {
      const double rows = std::min(steps, std::floor(cfg.duration / p.interval)) + 1.0;
      e.terms.push_back({count_text(rows) + " rows of probe \"" + p.name + "\"", path + ".interval", rows * 6 * sizeof(double)});
    }
    if (p.type == "velocity_field") {
      const double cells = double(p.radial_bins) * double(p.height_bins);
      e.terms.push_back({count_text(cells) + " cells of probe \"" + p.name + "\"", path + ".radial_bins",
                         cells * 4 * sizeof(double)});
    }
    if (p.type != "wall_pressure") continue;
    const double cells = double(p.angle_bins) * double(p.height_bins);
    e.terms.push_back({count_text(cells) + " cells of probe \"" + p.name + "\"", path + ".angle_bins",
                       cells * 5 * sizeof(double)});
    if (p.history_interval <= 0.0) continue;
    const double rows = std::min(steps, std::floor(cfg.duration / p.history_interval)) + 1.0;
    const double row = 2.0 * (sizeof(double) + sizeof(std::vector<double>)) + malloc_bytes(p.height_bins * 8.0);
    e.terms.push_back({count_text(rows) + " history rows of probe \"" + p.name + "\"", path + ".history_interval",
                       rows * row});
  }
}

}  // namespace

// Without recursion: any depth is safe.
double json_heap_bytes(const json& root) {
  double bytes = 0.0;
  std::vector<const json*> todo{&root};
  while (!todo.empty()) {
    const json& j = *todo.back();
    todo.pop_back();
    if (j.is_object()) {
      bytes += malloc_bytes(48);  // the std::map
      for (auto it = j.begin(); it != j.end(); ++it) {
        bytes += malloc_bytes(32 + sizeof(std::string) + sizeof(json)) + string_heap(it.key());
        todo.push_back(&*it);
      }
    } else if (j.is_array()) {
      const double capacity = j.empty() ? 0.0 : std::exp2(std::ceil(std::log2(double(j.size()))));
      bytes += malloc_bytes(24) + (j.empty() ? 0.0 : malloc_bytes(capacity * sizeof(json)));
      for (const auto& e : j) todo.push_back(&e);
    } else if (j.is_string()) {
      bytes += malloc_bytes(sizeof(std::string)) + string_heap(j.get_ref<const std::string&>());
    }
  }
  return bytes;
}

double MemoryEstimate::total() const {
  double sum = 0.0;
  for (const auto& t : terms) sum += t.bytes;
  return sum;
}

const MemoryTerm& MemoryEstimate::largest() const {
  return *std::max_element(terms.begin(), terms.end(),
                           [](const MemoryTerm& a, const MemoryTerm& b) { return a.bytes < b.bytes; });
}

std::string MemoryEstimate::describe() const {
  std::vector<const MemoryTerm*> order;
  for (const auto& t : terms) order.push_back(&t);
  std::stable_sort(order.begin(), order.end(), [](const MemoryTerm* a, const MemoryTerm* b) { return a->bytes > b->bytes; });
  std::string out = format_bytes(total()) + " (";
  for (std::size_t i = 0; i < order.size() && i < 3; ++i)
    out += (i ? ", " : "") + order[i]->what + " " + format_bytes(order[i]->bytes);
  return out + (order.size() > 3 ? ", ...)" : ")");
}

MemoryEstimate estimate_run_memory(const CaseConfig& cfg) {
  MemoryEstimate e;
  // The case file as parsed, besides its balls (counted with them); not copied to be measured.
  double rest = json_heap_bytes(json::object());
  if (cfg.source.is_object())
    for (auto it = cfg.source.begin(); it != cfg.source.end(); ++it)
      if (it.key() != "balls")
        rest += malloc_bytes(32 + sizeof(std::string) + sizeof(json)) + string_heap(it.key()) + json_heap_bytes(*it);
  e.terms.push_back({"case file as parsed, besides its balls", "$", 2.0 * rest});
  const BallCosts cost = ball_costs(cfg);
  add_ball_terms(cfg, cost, e);
  add_drop_terms(cfg, cost, e);
  add_probe_terms(cfg, e);
  return e;
}

MemoryLimit run_memory_limit() {
  MemoryLimit limit{limits::kRunMemoryBytes, "the limit of " + format_bytes(limits::kRunMemoryBytes) + " for one run"};
  if (const auto machine = available_memory(); machine && machine->bytes < limit.bytes)
    limit = {machine->bytes, "the " + format_bytes(machine->bytes) + " this machine has available (" + machine->source + ")"};
  return limit;
}

void check_run_memory(const CaseConfig& cfg, const MemoryLimit& limit) {
  const MemoryEstimate e = estimate_run_memory(cfg);
  if (e.total() <= limit.bytes) return;
  const MemoryTerm& big = e.largest();
  throw CaseError(big.field, "the run would need about " + e.describe() + ", more than " + limit.source +
                                 "; the largest part is " + big.what + ": make it smaller");
}

void check_case_copy_fits(const json& j) {
  const auto room = available_memory();
  if (!room) return;
  const double bytes = json_heap_bytes(j);
  if (bytes > 0.75 * room->bytes)
    throw CaseError("$", "the case as read takes " + format_bytes(bytes) + "; the copy a run keeps would take more than "
                         "three quarters of the " + format_bytes(room->bytes) + " this process can still take (" +
                             room->source + ")");
}

std::string format_bytes(double bytes) {
  char buf[48];
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 6) bytes /= 1024.0, ++u;
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : bytes < 10.0 ? "%.2f %s" : bytes < 100.0 ? "%.1f %s" : "%.0f %s",
                bytes, units[u]);
  return buf;
}

}  // namespace silodem
