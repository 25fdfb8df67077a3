#pragma once
// Plausibility limits of the case file's quantities (SI units). They are far outside any granular
// silo, and they keep every derived quantity (ball masses r³ρ, ω0 = √(k/m), step counts) finite,
// so a slip such as 1e308 for a radius is refused where it was written.
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
inline constexpr double kFactor = 1e6;          // dimensionless tolerances p_acc, p_f, p_ft, p_N
inline constexpr long kDropCount = 1000000000;  // drop attempts
inline constexpr double kWallBalls = 2e6;       // listed and wall balls, estimated before each wall is built

}  // namespace silodem::limits
