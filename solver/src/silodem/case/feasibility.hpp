#pragma once
// Checks that need more than one field: whether the scene can hold and release its balls, and
// whether the time step can be stable. Each refusal is a CaseError naming the field to change.
#include <string>

#include "silodem/case/case_config.hpp"

namespace silodem {

/// An upper bound on the balls build_wall() makes for `w`, computed before building so that a
/// huge silo or a tiny spacing is refused instead of exhausting memory.
double estimated_wall_balls(const WallSpec& w);

/// Every wall must hold the smallest mobile ball (listed or dropped), and every outlet must let it
/// pass. `walls_path` is the JSON path of the walls array.
void check_wall_geometry(const CaseConfig& cfg, const std::string& walls_path);

/// Δt must be below the integrator's stability limit for every pair the case can form
/// (integrate/stability.hpp). `dt_path` names the field that set Δt.
void check_time_step(const CaseConfig& cfg, const std::string& dt_path);

}  // namespace silodem
