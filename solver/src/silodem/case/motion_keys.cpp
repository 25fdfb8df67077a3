#include "silodem/case/motion_keys.hpp"

#include "silodem/case/contact_keys.hpp"
#include "silodem/case/limits.hpp"

namespace silodem::case_keys {

namespace {

Vec3 unit(const JsonReader& r, const std::string& key) {
  const Vec3 v = r.vec3_within(key, limits::kLength, "");
  require(v.norm() > 0.0, r, key, "must not be the zero vector");
  return v.normalized();
}

}  // namespace

MotionLaw read_motion(const JsonReader& r) {
  MotionLaw m;
  m.start_time = r.number_in_or("start_time", 0.0, limits::kTime, "s", 0.0);
  if (const auto o = r.opt_object("oscillation")) {
    m.direction = unit(*o, "direction");
    m.amplitude = positive(*o, "amplitude", limits::kLength, "m");
    m.frequency = positive(*o, "frequency", 1.0 / limits::kDtMin, "Hz");
    m.phase = o->number_in_or("phase", -2.0 * kPi, 2.0 * kPi, "rad", 0.0);
    o->finish();
  }
  if (const auto o = r.opt_object("rotation")) {
    m.centre = o->vec3_within("centre", limits::kLength, "m");
    m.axis = unit(*o, "axis");
    m.angular_speed = o->number_in("angular_speed", -limits::kSpinRate, limits::kSpinRate, "rad/s");
    require(m.angular_speed != 0.0, *o, "angular_speed", "must not be 0 (leave out \"rotation\" for a wall that does not turn)");
    o->finish();
  }
  require(m.amplitude > 0.0 || m.angular_speed != 0.0, r, "",
          "give \"oscillation\" (direction, amplitude, frequency, phase) or \"rotation\" (centre, axis, angular_speed), "
          "or both");
  r.finish();
  return m;
}

}  // namespace silodem::case_keys
