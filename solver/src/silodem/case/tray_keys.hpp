#pragma once
// A "tray" wall's keys (docs/case-format.md "walls"): seed 001's vibrating tray, a floor with slots
// and two side walls, one row of balls deep for the planar mode or a box with a depth.
#include "silodem/case/case_config.hpp"
#include "silodem/case/json_reader.hpp"

namespace silodem::case_keys {

/// Reads length, height, depth and slots into `w` (its radii and spacing already read); refuses
/// slots off the floor or overlapping, and a box net with holes.
void read_tray(const JsonReader& r, WallSpec& w);

}  // namespace silodem::case_keys
