#pragma once
// The keys of the seeds' vessels among the walls (docs/case-format.md "walls"): seed 001's "tray", a
// floor with slots and two side walls, and seed 003's "drum", a polygon about a horizontal axis with
// lifters; each one row of balls deep for the planar mode, or with a depth or length.
#include "silodem/case/case_config.hpp"
#include "silodem/case/json_reader.hpp"

namespace silodem::case_keys {

/// Reads length, height, depth and slots into `w` (its radii and spacing already read); refuses
/// slots off the floor or overlapping, and a box net with holes.
void read_tray(const JsonReader& r, WallSpec& w);

/// Reads sides, length and lifters into `w` (diameter read already); refuses lifters that do not
/// stand on face middles or reach past the axis, and an end-plate net with holes.
void read_drum(const JsonReader& r, WallSpec& w);

}  // namespace silodem::case_keys
