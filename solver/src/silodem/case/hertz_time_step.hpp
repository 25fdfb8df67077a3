#pragma once
// The stability bound of a Hertz scene (docs/theory.md §10.9). A Hertz contact stiffens with its
// overlap, so no step follows from the materials alone: the bound takes the deepest overlap an
// impact of the scene can reach — at the largest approach speed its initial velocities, drops and
// free fall under gravity can produce — and tests the scheme's one-contact limit (integrate/
// stability.hpp) on the tangent stiffness there, for the normal mode and the Mindlin tangential one.
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/integrate/stability.hpp"

namespace silodem {

/// The largest speed a ball of the scene can reach, if no collision gives one ball more than its
/// own energy: v_max = √(v0² + 2|g|H), with v0 the largest initial speed (mobile balls, the released
/// drops' release_speed) and H the drop along g from the highest top of a mobile ball (or a drop
/// at its release point) to the lowest top of any ball of the scene.
struct SceneSpeed {
  double speed = 0.0, initial = 0.0, fall_height = 0.0;  // m/s, m/s, m
};
SceneSpeed largest_speed(const CaseConfig& cfg);

/// One contact mode's stability limit, with what the refusal message says about it.
struct ModeLimit {
  StabilityLimit limit{0.0, ""};
  std::string pair;    // "a / b (fixed)"
  std::string detail;  // the mode, its ω and ζ, and how they were found
};

/// Every pair of ball kinds of a Hertz scene, normal mode and (with "mindlin") tangential mode,
/// at the peak of an impact at the largest approach speed: v_max against a fixed ball, 2 v_max
/// between two mobile ones. Empty when nothing can approach (v_max = 0).
std::vector<ModeLimit> hertz_mode_limits(const CaseConfig& cfg);

}  // namespace silodem
