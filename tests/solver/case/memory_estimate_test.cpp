// The run-memory estimate (case/memory_estimate.hpp) against what a run really takes from the
// heap: this executable counts every byte operator new hands out (malloc_usable_size, so malloc's
// rounding is counted as the allocator does it) and keeps the peak. A case is read and run as
// `silodem run` does it; the estimate must cover that peak without overstating it by more than 2×.
// And the refusals: a count no machine holds is refused naming its field.
#include <gtest/gtest.h>

#include <malloc.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <new>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/case/json_text.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/case/memory_estimate.hpp"
#include "silodem/run/simulation.hpp"

namespace {
std::atomic<long long> g_live{0}, g_peak{0};
constexpr long long kHeader = 8;  // glibc's chunk header, beside the usable size

void* counted(std::size_t n) {
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  const long long now = g_live += (long long)malloc_usable_size(p) + kHeader;
  for (long long peak = g_peak; now > peak && !g_peak.compare_exchange_weak(peak, now);) {
  }
  return p;
}
void uncounted(void* p) {
  if (!p) return;
  g_live -= (long long)malloc_usable_size(p) + kHeader;
  std::free(p);
}
}  // namespace

void* operator new(std::size_t n) { return counted(n); }
void* operator new[](std::size_t n) { return counted(n); }
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete[](void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t) noexcept { uncounted(p); }
// The nothrow forms too (std::stable_sort's buffer takes them): every form of new and delete must
// be replaced together, or one allocator's block is freed by the other.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted(n);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p, const std::nothrow_t&) noexcept { uncounted(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { uncounted(p); }

using namespace silodem;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json material() { return {{"density", 2500}, {"stiffness", 2e4}, {"damping_ratio", 0.2}, {"reference_radius", 0.002}}; }

json floor_wall() {
  return {{"name", "floor"}, {"type", "disk"},       {"material", "g"},   {"radius", {0.002, 0.002}},
          {"spacing", 0.003}, {"centre", {0, 0, 0}}, {"diameter", 0.16}};
}

/// n mobile balls in a loose lattice above the floor, with velocities (as a generated bed is written).
json listed_case(int n) {
  json balls = json::array();
  for (int i = 0; i < n; ++i) {
    const int a = i % 30, b = (i / 30) % 30, c = i / 900;
    balls.push_back({{"id", "ball" + std::to_string(i)}, {"material", "g"}, {"radius", 0.0019},
                     {"position", {(a - 15) * 0.0041, (b - 15) * 0.0041, 0.005 + c * 0.0041}},
                     {"velocity", {0.0, 0.0, -0.01 * (i % 7)}}});
  }
  return {{"name", "listed"}, {"materials", {{"g", material()}}}, {"balls", balls}, {"walls", {floor_wall()}},
          {"time", {{"duration", 2e-3}, {"dt_per_contact_time", 0.02}}}};
}

/// n drops onto the floor, one per step, each placed at its first contact.
json drops_case(int n) {
  return {{"name", "drops"},
          {"materials", {{"g", material()}}},
          {"walls", {floor_wall()}},
          {"drops",
           {{"material", "g"}, {"radius", {0.0015, 0.002}}, {"z0", 0.05}, {"count", n},
            {"inlet", {{"x", {-0.05, 0.05}}, {"y", {-0.05, 0.05}}}}}},
          {"time", {{"duration", 0.01}, {"dt_per_contact_time", 0.02}}},
          {"output", {{"probes", {{{"type", "drops"}}}}}}};
}

struct Measured {
  double peak_bytes, estimate_bytes;
  json summary;
};

/// Reads the case's text and runs it as `silodem run` does, counting the heap's peak above the start.
Measured run_counted(const json& c, const std::string& out) {
  const std::string text = c.dump(2);
  const long long start = g_live;
  g_peak = start;
  Measured m{};
  {
    const CaseConfig cfg = load_case(parse_case_text(text, "case.json"));
    m.estimate_bytes = estimate_run_memory(cfg).total();
    m.summary = run_case(cfg, {fs::temp_directory_path() / out, false, false});
  }
  m.peak_bytes = double(g_peak - start);
  fs::remove_all(fs::temp_directory_path() / out);
  return m;
}

std::string refusal(const CaseConfig& cfg, const MemoryLimit& limit) {
  try {
    check_run_memory(cfg, limit);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "accepted";
}

std::string load_error(const json& c) {
  try {
    load_case(c);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST(MemoryEstimate, CoversTheHeapPeakOfARunOfListedBalls) {
  const Measured m = run_counted(listed_case(4000), "silodem_memory_listed");
  EXPECT_GT(m.summary["run"]["steps"].get<long>(), 10);
  EXPECT_EQ(m.summary["memory"]["estimated_bytes"].get<double>(), m.estimate_bytes);
  EXPECT_GE(m.estimate_bytes, m.peak_bytes);
  EXPECT_LE(m.estimate_bytes, 2.0 * m.peak_bytes);
  std::printf("listed: peak %.0f B, estimate %.0f B (%.2f)\n", m.peak_bytes, m.estimate_bytes, m.estimate_bytes / m.peak_bytes);
}

TEST(MemoryEstimate, CoversTheHeapPeakOfARunThatPlacesAllItsDrops) {
  const Measured m = run_counted(drops_case(2000), "silodem_memory_drops");
  // A drop whose placed position overlaps a ball that moved meanwhile is rejected: most are placed.
  ASSERT_GE(m.summary["drops"]["placed"].get<long>(), 1600) << m.summary["drops"].dump();
  EXPECT_GE(m.estimate_bytes, m.peak_bytes);
  EXPECT_LE(m.estimate_bytes, 2.0 * m.peak_bytes);
  std::printf("drops: peak %.0f B, estimate %.0f B (%.2f)\n", m.peak_bytes, m.estimate_bytes, m.estimate_bytes / m.peak_bytes);
}

TEST(MemoryEstimate, CoversTheHeapPeakOfAFrictionalRun) {
  // The frictional loop's per-slot results, the contact history and the rotation arrays.
  json c = listed_case(4000);
  c["contact"] = {{"tangential", "linear_history"}, {"rolling", "constant_torque"}};
  for (auto& [name, m] : c["materials"].items()) m["friction"] = 0.5, m["rolling_friction"] = 0.01;
  const Measured m = run_counted(c, "silodem_memory_friction");
  EXPECT_GT(m.summary["run"]["steps"].get<long>(), 10);
  EXPECT_GE(m.estimate_bytes, m.peak_bytes);
  EXPECT_LE(m.estimate_bytes, 2.0 * m.peak_bytes);
  std::printf("friction: peak %.0f B, estimate %.0f B (%.2f)\n", m.peak_bytes, m.estimate_bytes, m.estimate_bytes / m.peak_bytes);
}

TEST(MemoryEstimate, ACountNoMachineHoldsIsRefusedNamingItsField) {
  // The loader itself refuses it, so `check` and `run` alike.
  const std::string e = load_error(drops_case(1000000000));
  EXPECT_EQ(e.rfind("$.drops.count: the run would need about ", 0), 0u) << e;
  EXPECT_NE(e.find("1e+09 drops"), std::string::npos) << e;
  // Against the stated limit alone, whatever this machine has: 10^9 drops at a few hundred bytes
  // each at the very least is far beyond 64 GiB.
  CaseConfig cfg = load_case(drops_case(1000));
  EXPECT_EQ(refusal(cfg, {limits::kRunMemoryBytes, "the stated limit"}), "accepted");
  cfg.drops->count = 1000000000;
  EXPECT_GT(estimate_run_memory(cfg).total(), 1e9 * 300.0);
  EXPECT_EQ(refusal(cfg, {limits::kRunMemoryBytes, "the stated limit"}).rfind("$.drops.count: ", 0), 0u);
}

TEST(MemoryEstimate, TheLimitIsTheLowerOfTheStatedOneAndTheMachines) {
  const MemoryLimit limit = run_memory_limit();
  EXPECT_LE(limit.bytes, limits::kRunMemoryBytes);
  EXPECT_GT(limit.bytes, 0.0);
  // A limit below the case's estimate refuses it, naming the largest part: here the listed balls.
  const CaseConfig cfg = load_case(listed_case(4000));
  const double need = estimate_run_memory(cfg).total();
  EXPECT_EQ(refusal(cfg, {need * 1.01, "enough"}), "accepted");
  const std::string e = refusal(cfg, {need * 0.99, "a small test limit"});
  EXPECT_EQ(e.rfind("$.balls: ", 0), 0u) << e;
  EXPECT_NE(e.find("more than a small test limit"), std::string::npos) << e;
  EXPECT_NE(e.find("4000 listed balls"), std::string::npos) << e;
}
