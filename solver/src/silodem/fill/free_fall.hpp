#pragma once
// Analytic free fall to the first contact (Algorithm 2, (12)–(16)).
#include <cstddef>
#include <optional>

#include "silodem/scene/particles.hpp"

namespace silodem {

/// Fall height h at which a ball of radius r0 released at (x0, y0, z0) first touches a ball of
/// radius rj at xj: the smaller root of h² − 2(z0 − zj)h + c_j = 0 (15). docs/model.md §4.1 Reading:
/// the printed linear term has the wrong sign; the first contact is h = (z0 − zj) − √D_j with
/// D_j = (r0 + rj)² − (horizontal distance)². Empty unless D_j > 0 (D_j = 0 is a graze).
/// The result may be negative: the ball would start overlapping, or below, ball j.
std::optional<double> first_contact_height(const Vec3& start, double r0, const Vec3& xj, double rj);

struct FirstContact {
  // PlacementOverlaps: the contact point lies inside a receding ball (see find_first_contact).
  enum class Kind { Contact, NoObstacle, StartOverlaps, PlacementOverlaps } kind = Kind::NoObstacle;
  double h = 0.0;             // fall height to the contact
  std::size_t obstacle = 0;   // index of the ball touched
};

/// The governing contact is the smallest h over all candidates, the highest obstacle (Fig. 2).
/// A ball whose start position already overlaps a ball is reported as StartOverlaps.
/// Algorithm 2 treats every obstacle as static. With g_abs > 0 a ball that falls at least as fast
/// as the new ball would when passing its height (v_z ≤ −√(2 g (z0 − z_j))) is no obstacle: in free
/// flight it keeps that lead, so a ball released now never catches it. Without this, drops placed
/// faster than the pile spreads (recycled leavers, one per step) land on earlier drops still in
/// flight and stack into towers up to the inlet (the feeder then stalls).
FirstContact find_first_contact(const Particles& p, const Vec3& start, double r0, double g_abs = 0.0);

}  // namespace silodem
