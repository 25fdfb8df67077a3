#pragma once
// A wall's "motion" (docs/case-format.md "Walls in motion"): a harmonic translation, a rotation
// about an axis, or their sum (motion/motion_law.hpp).
#include "silodem/case/json_reader.hpp"
#include "silodem/motion/motion_law.hpp"

namespace silodem::case_keys {

/// Reads a wall's motion object; refuses one that moves nothing.
MotionLaw read_motion(const JsonReader& r);

}  // namespace silodem::case_keys
