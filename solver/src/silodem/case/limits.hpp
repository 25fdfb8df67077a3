#pragma once
// Plausibility limits of the case file's quantities (SI units). They are far outside any granular
// silo, and they keep every derived quantity (ball masses r³ρ, ω0 = √(k/m), step counts) finite,
// so a slip such as 1e308 for a radius is refused where it was written.
#include <cstddef>

namespace silodem::limits {

inline constexpr double kLength = 1e4;          // m: |coordinates| and sizes
inline constexpr double kRadiusMin = 1e-9;      // m
inline constexpr double kDensityMin = 1e-3;     // kg/m³
inline constexpr double kDensityMax = 1e6;      // kg/m³
inline constexpr double kStiffness = 1e15;      // N/m
inline constexpr double kDamping = 1e12;        // N s/m
inline constexpr double kDampingRatio = 1e3;    // clamped contacts only; unclamped ones need ζ < 1
inline constexpr double kContactTimeMin = 1e-12;  // s
inline constexpr double kContactTimeMax = 1e3;    // s
inline constexpr double kSpeed = 1e6;           // m/s: |velocity components|
inline constexpr double kGravity = 1e6;         // m/s²: |gravity components|
inline constexpr double kTime = 1e9;            // s: durations, event times, intervals
inline constexpr double kDtMin = 1e-15;         // s
inline constexpr double kSteps = 1e12;          // duration/Δt: a run longer than this never ends
inline constexpr double kSpinRate = 1e7;       // rad/s
inline constexpr double kFriction = 10.0;       // μ, μ_r: far above any granular material's
inline constexpr double kModulus = 1e13;        // Pa, above diamond's 1.2e12
inline constexpr double kFactor = 1e6;          // dimensionless tolerances p_acc, p_f, p_ft, p_N
inline constexpr long kDropCount = 1000000000;  // drop attempts
inline constexpr double kWallBalls = 2e6;       // listed and wall balls, estimated before each wall is built
inline constexpr double kGeneratedBalls = 2e7;  // grains of one `generate` entry, bounded before any is made

// Resources, checked before anything is allocated for them (docs/case-format.md, "Limits").
// 10^6 listed balls take 150 MB written compactly and 330 MB as Python's json.dump(indent=2)
// writes them with velocities: the file limit holds the latter with room to spare.
inline constexpr unsigned long kCaseFileBytes = 512ul << 20;  // 512 MiB
inline constexpr int kJsonDepth = 256;  // nested arrays/objects; a case needs fewer than 10
// The run's estimated memory (case/memory_estimate.hpp) at most this, and at most what the machine
// has available: 10^8 balls at about 600 B each, 100 times the largest bed measured.
inline constexpr double kRunMemoryBytes = 64.0 * (1ul << 30);  // 64 GiB
// A name that becomes a file or directory name (case, probe, variant axis and value): with
// ".partial-<pid>", ".checkpoint" or "_history.csv" added it stays far below NAME_MAX (255 bytes).
inline constexpr std::size_t kNameBytes = 100;
inline constexpr double kVariantRuns = 1000;  // runs one "variants" product may make

}  // namespace silodem::limits
