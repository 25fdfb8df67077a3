#include "silodem/case/surface_keys.hpp"

#include <cmath>
#include <set>

#include "silodem/case/limits.hpp"
#include "silodem/case/path_name.hpp"
#include "silodem/scene/surface.hpp"

namespace silodem::case_keys {

using nlohmann::json;

namespace {

/// "axis": [x, y] — the vertical line through (x, y, 0) — or {"point": [x, y, z], "direction":
/// [dx, dy, dz]}, any line (a drum's horizontal axis).
void read_axis(const JsonReader& r, SurfaceSpec& s) {
  if (r.raw("axis").is_object()) {
    const JsonReader a = r.object("axis");
    s.axis_point = a.vec3_within("point", limits::kLength, "m");
    const Vec3 d = a.vec3_within("direction", limits::kLength, "");
    if (!(d.norm() > 0.0)) a.fail("direction", "must not be the zero vector");
    s.axis_direction = d.normalized();
    if (s.axis_direction.x() == 0.0 && s.axis_direction.y() == 0.0 && s.axis_direction.z() > 0.0)
      s.axis_direction = Vec3::UnitZ();  // exactly vertical: the same surface as "axis": [x, y]
    a.finish();
    return;
  }
  const json& axis = r.array("axis");
  if (axis.size() != 2)
    r.fail("axis", "give the vertical axis as [x, y] in m, or {\"point\": [x, y, z], \"direction\": [dx, dy, dz]}");
  s.axis_point = Vec3(json_number_in(axis[0], r.child_path("axis") + "[0]", -limits::kLength, limits::kLength, "m"),
                      json_number_in(axis[1], r.child_path("axis") + "[1]", -limits::kLength, limits::kLength, "m"), 0.0);
}

void read_surface(const JsonReader& r, CaseConfig& cfg, std::set<std::string>& names) {
  const std::string name = r.string("name");
  require_path_name(name, r.child_path("name"));  // its load is reported under this name
  if (!names.insert(name).second) r.fail("name", "duplicate surface name \"" + name + "\"");
  SurfaceSpec s;
  s.material = r.string("material");
  if (!cfg.materials.count(s.material)) r.fail("material", "no material named \"" + s.material + "\"");
  read_axis(r, s);
  s.angular_speed = r.number_in_or("angular_speed", -limits::kSpinRate, limits::kSpinRate, "rad/s", 0.0);
  const json& profile = r.array("profile");
  if (profile.size() < 2) r.fail("profile", "give at least two points [rho, z]: one segment");
  std::vector<std::pair<double, double>> pts;
  for (std::size_t k = 0; k < profile.size(); ++k) {
    const std::string at = r.child_path("profile") + "[" + std::to_string(k) + "]";
    if (!profile[k].is_array() || profile[k].size() != 2) throw CaseError(at, "expected [rho, z] in m");
    const double rho = json_number_in(profile[k][0], at + "[0]", 0.0, limits::kLength, "m");
    const double z = json_number_in(profile[k][1], at + "[1]", -limits::kLength, limits::kLength, "m");
    if (k > 0 && rho == pts.back().first && z == pts.back().second)
      throw CaseError(at, "repeats the point before it: a segment needs two different ends");
    pts.emplace_back(rho, z);
  }
  r.finish();
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    s.name = pts.size() == 2 ? name : name + "_" + std::to_string(k);
    std::tie(s.rho0, s.z0) = pts[k];
    std::tie(s.rho1, s.z1) = pts[k + 1];
    cfg.surfaces.push_back(s);
  }
}

}  // namespace

void read_surfaces(const JsonReader& r, CaseConfig& cfg) {
  const json& ss = r.array("surfaces");
  std::set<std::string> names;
  for (std::size_t i = 0; i < ss.size(); ++i)
    read_surface(JsonReader(ss[i], r.child_path("surfaces") + "[" + std::to_string(i) + "]"), cfg, names);
}

void check_surface_overlaps(const CaseConfig& cfg, const std::string& path) {
  for (const SurfaceSpec& spec : cfg.surfaces) {
    const Surface s = surface_from(spec, 0);
    for (const BallSpec& b : cfg.balls) {
      if (b.fixed) continue;
      const double overlap = b.radius - surface_gap(s, b.position).distance;
      if (overlap > cfg.guards.max_overlap_ratio * b.radius)
        throw CaseError(path, "ball \"" + b.id + "\" starts " + format_number(overlap) + " m deep in surface \"" +
                                  spec.name + "\" (more than the overlap guard's " +
                                  format_number(cfg.guards.max_overlap_ratio) + " of its radius)");
    }
  }
}

}  // namespace silodem::case_keys
