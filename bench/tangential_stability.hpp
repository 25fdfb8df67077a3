#pragma once
// bench_stability's tangential mode (bench/tangential_stability.cpp).
#include <nlohmann/json.hpp>
#include <ostream>

/// One row per scheme and ζ_t: the measured largest stable Ω_t, its theory and the loader's rules.
nlohmann::json tangential_rows(int steps);
/// The rows as the Markdown section of reports/stability.md.
void write_tangential_md(std::ostream& md, const nlohmann::json& rows, int steps);
