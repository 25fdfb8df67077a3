#include "silodem/case/vessel_keys.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "silodem/case/limits.hpp"

namespace silodem::case_keys {

void read_tray(const JsonReader& r, WallSpec& w) {
  for (const char* key : {"diameter", "hole_diameter"})
    if (r.has(key)) r.fail(key, "a tray has a length, a height, a depth and slots, not a diameter");
  w.length = r.number_in("length", limits::kRadiusMin, limits::kLength, "m");
  w.height = r.number_in("height", limits::kRadiusMin, limits::kLength, "m");
  w.depth = r.number_in_or("depth", 0.0, limits::kLength, "m", 0.0);
  // A box's faces are square nets: closed only while the diagonal gap s/√2 is under r_min.
  if (w.depth > 0.0 && !(w.spacing < std::sqrt(2.0) * w.r_min))
    r.fail("spacing", "a tray with a depth is a square net of balls: spacing " + format_number(w.spacing) +
                          " m must be below sqrt(2) r_min = " + format_number(std::sqrt(2.0) * w.r_min) + " m");
  if (r.has("slots")) {
    const nlohmann::json& slots = r.array("slots");
    for (std::size_t i = 0; i < slots.size(); ++i) {
      const JsonReader s(slots[i], r.child_path("slots") + "[" + std::to_string(i) + "]");
      TraySlot slot;
      slot.x = s.number_in("x", -limits::kLength, limits::kLength, "m");
      slot.width = s.number_in("width", limits::kRadiusMin, limits::kLength, "m");
      s.finish();
      w.slots.push_back(slot);
    }
    std::sort(w.slots.begin(), w.slots.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  }
  // The edge balls sit at x ± (width/2 + r̄): each slot must leave floor on both sides of it.
  const double rm = 0.5 * (w.r_min + w.r_max);
  double floor_from = -0.5 * w.length;
  for (const auto& slot : w.slots) {
    if (slot.x - 0.5 * slot.width - rm < floor_from)
      r.fail("slots", "the slot at x = " + format_number(slot.x) + " m (width " + format_number(slot.width) +
                          " m) overlaps the tray's end or the slot before it (edge balls at x +- (width/2 + r))");
    floor_from = slot.x + 0.5 * slot.width + rm;
  }
  if (floor_from > 0.5 * w.length)
    r.fail("slots", "the last slot reaches past the tray's end at x = " + format_number(0.5 * w.length) + " m");
}

void read_drum(const JsonReader& r, WallSpec& w) {
  if (r.has("hole_diameter")) r.fail("hole_diameter", "a drum is closed");
  w.sides = int(r.integer_in_or("sides", 3, 100000, 24));
  w.length = r.number_in_or("length", 0.0, limits::kLength, "m", 0.0);
  if (w.length > 0.0 && !(w.spacing < std::sqrt(2.0) * w.r_min))
    r.fail("spacing", "a drum with a length has end plates of square nets: spacing " + format_number(w.spacing) +
                          " m must be below sqrt(2) r_min = " + format_number(std::sqrt(2.0) * w.r_min) + " m");
  if (const auto l = r.opt_object("lifters")) {
    w.lifters = int(l->integer_in_or("count", 1, w.sides, 1));
    w.lifter_height = l->number_in("height", limits::kRadiusMin, limits::kLength, "m");
    l->finish();
    if (w.sides % w.lifters != 0)
      r.fail("lifters", "the " + std::to_string(w.lifters) + " lifters must stand on face middles: sides (" +
                            std::to_string(w.sides) + ") must be a multiple of their count");
    if (w.lifter_height >= 0.5 * w.diameter * std::cos(kPi / w.sides))
      r.fail("lifters", "a lifter of height " + format_number(w.lifter_height) + " m reaches the axis");
  }
}

}  // namespace silodem::case_keys
