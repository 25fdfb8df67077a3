#pragma once
// Checks that need more than one field: whether the scene can hold and release its balls, and
// whether the time step can be stable. Each refusal is a CaseError naming the field to change.
#include <functional>
#include <string>

#include "silodem/case/case_config.hpp"

namespace silodem {

/// An upper bound on the balls build_wall() makes for `w`, computed before building so that a
/// huge silo or a tiny spacing is refused instead of exhausting memory.
double estimated_wall_balls(const WallSpec& w);

/// Every wall must hold the smallest mobile ball (listed or dropped), and every outlet must let it
/// pass. `walls_path` is the JSON path of the walls array.
void check_wall_geometry(const CaseConfig& cfg, const std::string& walls_path);

/// The smallest radius of the scene: listed and wall balls and the drops' smallest (m).
double smallest_radius(const CaseConfig& cfg);

/// A ball may move at most guards.max_travel_ratio of the smallest radius per step, or it can pass
/// through a ball between two steps without one sample in contact (run/guards.hpp, which stops a
/// run that gets there). Refuses a listed mobile ball's initial velocity, and the released drops'
/// release_speed (at `release_speed_path`), that already break it; `path_of(i)` names ball i.
void check_initial_travel(const CaseConfig& cfg, const std::function<std::string(std::size_t)>& path_of,
                          const std::string& release_speed_path);

/// Δt must be below the integrator's stability limit for every pair the case can form
/// (integrate/stability.hpp). `dt_path` names the field that set Δt.
void check_time_step(const CaseConfig& cfg, const std::string& dt_path);

}  // namespace silodem
