#include "harness/backends/planar_frame.hpp"

#include <cmath>

namespace harness {

silodem::Mat3 planar_turn() {
  silodem::Mat3 q;
  q << 1.0, 0.0, 0.0,  //
      0.0, 0.0, 1.0,   //
      0.0, -1.0, 0.0;
  return q;
}

Translation in_frame(Translation tr, const silodem::Mat3& q) {
  const auto turn = [&](silodem::Vec3& v) { v = q * v; };
  const auto turn_ball = [&](TranslatedBall& b) { turn(b.x), turn(b.v), turn(b.w); };
  for (auto& b : tr.balls) turn_ball(b);
  for (auto& ev : tr.events) turn(ev.centre), turn(ev.velocity), turn_ball(ev.ball);
  for (auto& m : tr.motions) turn(m.law.direction), turn(m.law.centre), turn(m.law.axis);
  for (auto& x : tr.box_holds) turn(x);
  tr.frame = q * tr.frame;
  return tr;
}

std::string planar_limits(const silodem::CaseConfig& cfg, const Translation& tr, const std::string& code,
                          PlanarInertias has) {
  if (cfg.dimension != 2) return "";
  if (!cfg.surfaces.empty())
    return "the planar mode's smooth surfaces are not translated for " + code + " (its 2-D run lies in x-y: the "
           "surfaces' regions would have to turn with the axes)";
  for (const auto& ev : tr.events)
    if (ev.type == "close_outlet")
      return "a closure in the planar mode is not translated for " + code + " (its slab region would turn with the axes)";
  const double kappa = cfg.inertia_factor;
  if ((has.sphere && std::abs(kappa - 0.4) < 1e-12) || (has.disc && std::abs(kappa - 0.5) < 1e-12)) return "";
  std::string kinds = has.sphere && has.disc ? "spheres (I = 2/5 m r^2) or discs (1/2 m r^2)"
                      : has.disc             ? "discs only (I = 1/2 m r^2)"
                                             : "spheres only (I = 2/5 m r^2)";
  return code + " integrates planar grains as " + kinds + "; the case's grain inertia is " + std::to_string(kappa) +
         " m r^2";
}

std::string lammps_family_boundary(const silodem::CaseConfig& cfg) {
  return cfg.dimension == 2 ? "dimension 2\nboundary m m p\n" : "boundary m m m\n";
}

}  // namespace harness
