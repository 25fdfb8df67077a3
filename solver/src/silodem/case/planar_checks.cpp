#include "silodem/case/planar_checks.hpp"

#include <cmath>

#include "silodem/case/case_error.hpp"
#include "silodem/case/json_reader.hpp"

namespace silodem {

namespace {

bool in_plane(const Vec3& v) { return v.y() == 0.0; }
/// Along y (a spin the plane keeps): no x or z part.
bool along_normal(const Vec3& v) { return v.x() == 0.0 && v.z() == 0.0; }

void refuse(const std::string& path, const std::string& what) {
  throw CaseError(path, what + ": a planar case (\"dimension\": 2) keeps every grain in the plane y = 0, spinning about y");
}

void check_balls(const CaseConfig& cfg) {
  for (const auto& b : cfg.balls) {
    if (b.fixed) continue;  // a wall ball off the plane only bounds it (its force's y part is dropped)
    if (!in_plane(b.position)) refuse("$.balls", "ball \"" + b.id + "\" is at y = " + format_number(b.position.y()) + " m");
    if (!in_plane(b.velocity)) refuse("$.balls", "ball \"" + b.id + "\" has a velocity along y");
    if (!along_normal(b.angular_velocity)) refuse("$.balls", "ball \"" + b.id + "\" spins about x or z");
  }
}

void check_walls(const CaseConfig& cfg) {
  for (std::size_t i = 0; i < cfg.walls.size(); ++i) {
    const WallSpec& w = cfg.walls[i];
    const std::string path = "$.walls[" + std::to_string(i) + "]";
    if (w.type != "tray" && w.type != "drum")
      refuse(path, "wall \"" + w.name + "\" is a " + w.type + " of balls around a vertical axis, not a planar wall "
                   "(use a tray of depth 0 or a drum of length 0, list its balls in the plane, or use \"surfaces\")");
    if (w.depth != 0.0 || (w.type == "drum" && w.length != 0.0) || w.centre.y() != 0.0)
      refuse(path, w.type + " \"" + w.name + "\" must be one row deep (depth or length 0) at y = 0");
    if (!w.motion) continue;
    const MotionLaw& m = *w.motion;
    if ((m.amplitude != 0.0 && !in_plane(m.direction)) ||
        (m.angular_speed != 0.0 && (!along_normal(m.axis) || !in_plane(m.centre))))
      refuse(path + ".motion", "the law moves tray \"" + w.name + "\" out of the plane");
  }
}

void check_surfaces(const CaseConfig& cfg) {
  for (const auto& s : cfg.surfaces) {
    const std::string path = "$.surfaces (\"" + s.name + "\")";
    if (!in_plane(s.axis_point)) refuse(path, "its axis passes y = " + format_number(s.axis_point.y()) + " m");
    // About an axis in the plane or along y, a grain in the plane meets the surface along a normal
    // in the plane; any other axis would push it out.
    if (!in_plane(s.axis_direction) && !along_normal(s.axis_direction)) refuse(path, "its axis is neither in the plane nor along y");
    if (s.angular_speed != 0.0 && !along_normal(s.axis_direction))
      refuse(path, "it spins about an axis in the plane: its surface moves along y");
  }
}

void check_drops(const CaseConfig& cfg) {
  if (!cfg.drops) return;
  const DropSpec& d = *cfg.drops;
  if (d.y_min != 0.0 || d.y_max != 0.0) refuse("$.drops.inlet.y", "the inlet must be [0, 0]");
  for (const auto& xy : d.positions)
    if (xy[1] != 0.0) refuse("$.drops.positions", "a drop point has y0 = " + format_number(xy[1]) + " m");
}

void check_events(const CaseConfig& cfg) {
  for (std::size_t i = 0; i < cfg.events.size(); ++i) {
    const StageEvent& ev = cfg.events[i];
    if (ev.type == "move_wall" && !in_plane(ev.velocity))
      refuse("$.stages.events[" + std::to_string(i) + "].velocity", "the wall would move along y");
    if (ev.type == "open_outlet" && ev.release_mobile)
      for (const auto& b : cfg.balls)
        if (b.fixed && ev.names(b.id) && !in_plane(b.position))
          refuse("$.stages.events[" + std::to_string(i) + "]", "it sets free ball \"" + b.id + "\", which is off the plane");
  }
}

}  // namespace

void check_planar(const CaseConfig& cfg) {
  if (cfg.dimension != 2) return;
  if (!in_plane(cfg.gravity)) refuse("$.gravity", "gravity has a y part");
  check_balls(cfg);
  check_walls(cfg);
  check_surfaces(cfg);
  check_drops(cfg);
  check_events(cfg);
}

}  // namespace silodem
