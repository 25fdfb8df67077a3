#pragma once
// The starting scene must be one the contact law can evaluate: no two balls at the same centre
// and no pair already overlapping deeper than the overlap guard allows. Found in O(N) with one
// cell grid per octave of radius, so a few large balls among many small ones do not make every
// cell large.
//
// Same centre: the contact normal is (x_i − x_j)/|x_i − x_j|, 0/0 at equal centres (NaN forces
// at t = 0). Closer than kSameCentreFraction of the smaller radius it is a number the input's
// rounding sets: a coordinate carries an error of about 1e-16 |x|, which turns the normal by up
// to 1e-16 |x|/d — 1e-3 rad at d = 1e-6 r for a 1 mm ball 10 km (the largest coordinate
// accepted) from the origin, and more below. Such a pair is a ball written twice (a generator
// repeating a point); it is refused with that reason whatever the overlap guard allows.
//
// Deep overlap: a pair overlapping by more than guards.max_overlap_ratio of the smaller radius
// trips the overlap guard at the first step, whose message would blame the time step; refused
// here instead, naming both balls.
//
// Which pairs: a pair is tested when one of its balls is mobile. Wall balls overlap each other by
// design and never interact (neighbour/neighbour_list.hpp), so two fixed balls may share a centre
// harmlessly — unless their wall is set free by an "open_outlet" event with "release": "mobile":
// such balls then meet their neighbours, and only the same-centre test applies to them (they
// overlap their own wall's balls by design, and fly apart with that energy when released).
#include <functional>
#include <string>

#include "silodem/case/case_config.hpp"

namespace silodem {

inline constexpr double kSameCentreFraction = 1e-6;

/// Throws CaseError at the path `path_of(i)` of the later ball of the first offending pair
/// (in ball order), naming both balls, their distance and the reason.
void check_initial_contacts(const CaseConfig& cfg, const std::function<std::string(std::size_t)>& path_of);

}  // namespace silodem
