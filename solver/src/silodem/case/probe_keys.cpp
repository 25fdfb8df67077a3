#include "silodem/case/probe_keys.hpp"

#include <algorithm>
#include <set>
#include <string>

#include "silodem/case/case_error.hpp"
#include "silodem/case/contact_keys.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/case/path_name.hpp"
#include "silodem/case/surface_keys.hpp"

namespace silodem::case_keys {

using nlohmann::json;

namespace {

/// A sampled probe's `interval` (> 0), `from_time` and `to_time` (0: to the end).
void read_sampling_window(const JsonReader& p, ProbeSpec& s) {
  s.interval = p.number_in("interval", 0.0, limits::kTime, "s");
  require(s.interval > 0.0, p, "interval", "must be > 0 (a sample every this many seconds)");
  s.from_time = p.number_in_or("from_time", 0.0, limits::kTime, "s", 0.0);
  s.to_time = p.number_in_or("to_time", 0.0, limits::kTime, "s", 0.0);
  require(s.to_time == 0.0 || s.to_time > s.from_time, p, "to_time", "must be after from_time (0: to the end)");
}

void read_velocity_field(const JsonReader& p, ProbeSpec& s) {
  s.field_centre = p.vec3_or("centre", Vec3::Zero());
  s.field_radius = p.number_in("radius", 0.0, limits::kLength, "m");
  require(s.field_radius > 0.0, p, "radius", "must be > 0");
  const json& z = p.array("z");
  if (z.size() != 2 || !z[0].is_number() || !z[1].is_number() || !(z[1].get<double>() > z[0].get<double>()))
    p.fail("z", "give [z_low, z_high] in m with z_low < z_high");
  s.field_z[0] = z[0].get<double>(), s.field_z[1] = z[1].get<double>();
  s.radial_bins = int(p.integer_in_or("radial_bins", 1, 10000, 10));
  s.height_bins = int(p.integer_in_or("height_bins", 1, 10000, 10));
  read_sampling_window(p, s);
}

}  // namespace

void read_probes(const JsonReader& r, CaseConfig& cfg) {
  std::set<std::string> ids, names;
  for (const auto& b : cfg.balls) ids.insert(b.id);
  const json& ps = r.array("probes");
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const JsonReader p(ps[i], r.child_path("probes") + "[" + std::to_string(i) + "]");
    ProbeSpec s;
    s.type = p.choice_or("type", {"pair", "ball", "drops", "wall_pressure", "wall_load", "outflow", "section_force",
                                  "velocity_field", "charge", "area_fraction"},
                          "");
    s.name = p.string_or("name", s.type + std::to_string(i));
    require_path_name(s.name, p.child_path("name"));  // probes/<name>.csv
    require(names.insert(s.name).second, p, "name", "duplicate probe name \"" + s.name + "\"");
    const std::size_t want = s.type == "pair" ? 2 : s.type == "ball" ? 1 : 0;
    if (s.type == "wall_pressure") {
      s.wall = p.string("wall");
      bool found = false;
      for (const auto& w : cfg.walls) found = found || w.name == s.wall;
      if (!found) p.fail("wall", "no wall named \"" + s.wall + "\"");
      for (const auto& w : cfg.walls)
        if (w.name == s.wall && (w.type == "tray" || w.type == "drum"))
          p.fail("wall", "a wall_pressure map is for a cylinder, disk or cone; use a wall_load probe on a " + w.type);
      s.angle_bins = int(p.integer_in_or("angle_bins", 1, 3600, 12));
      s.height_bins = int(p.integer_in_or("height_bins", 1, 10000, 10));
      s.from_time = p.number_or("from_time", 0.0);
      s.history_interval = p.number_or("history_interval", 0.0);
      require(s.history_interval >= 0.0, p, "history_interval", "must be >= 0 (0: no history)");
      require(s.from_time >= 0.0, p, "from_time", "must be >= 0");
      p.number_in_or("history_interval", 0.0, limits::kTime, "s", 0.0);
      p.number_in_or("from_time", 0.0, limits::kTime, "s", 0.0);
      s.to_time = p.number_or("to_time", 0.0);
      p.number_in_or("to_time", 0.0, limits::kTime, "s", 0.0);
      require(s.to_time == 0.0 || s.to_time > s.from_time, p, "to_time", "must be after from_time (0: to the end)");
    } else if (s.type == "wall_load") {
      s.wall = p.string("wall");
      bool found = false;
      for (const auto& w : cfg.walls) found = found || w.name == s.wall;
      for (const auto& sf : cfg.surfaces) found = found || surface_of(sf.name, s.wall);
      if (!found) p.fail("wall", "no wall or surface named \"" + s.wall + "\"");
      s.interval = p.number_in_or("interval", 0.0, limits::kTime, "s", 0.0);
      s.from_time = p.number_in_or("from_time", 0.0, limits::kTime, "s", 0.0);
      s.to_time = p.number_in_or("to_time", 0.0, limits::kTime, "s", 0.0);
      require(s.to_time == 0.0 || s.to_time > s.from_time, p, "to_time", "must be after from_time (0: to the end)");
    } else if (s.type == "area_fraction") {
      if (cfg.dimension != 2) p.fail("type", "an area fraction is of discs in the plane: it needs \"dimension\": 2");
      for (const char* key : {"x", "z"}) {
        const json& range = p.array(key);
        if (range.size() != 2 || !range[0].is_number() || !range[1].is_number() || !(range[1].get<double>() > range[0].get<double>()))
          p.fail(key, std::string("give [") + key + "_low, " + key + "_high] in m with low < high");
        double* into = key[0] == 'x' ? s.field_x : s.field_z;
        into[0] = range[0].get<double>(), into[1] = range[1].get<double>();
      }
      s.radial_bins = int(p.integer_in_or("x_bins", 1, 10000, 10));
      s.height_bins = int(p.integer_in_or("z_bins", 1, 10000, 10));
      read_sampling_window(p, s);
    } else if (s.type == "charge") {
      s.wall = p.string("wall");
      if (std::none_of(cfg.walls.begin(), cfg.walls.end(), [&](const WallSpec& w) { return w.name == s.wall; }))
        p.fail("wall", "no wall named \"" + s.wall + "\" (a charge is taken about a wall of balls' axis)");
      s.interval = p.number_in_or("interval", 0.0, limits::kTime, "s", 0.0);
      s.from_time = p.number_in_or("from_time", 0.0, limits::kTime, "s", 0.0);
    } else if (s.type == "section_force") {
      s.plane_z = p.number_in("z", -limits::kLength, limits::kLength, "m");
      s.interval = p.number_in("interval", 0.0, limits::kTime, "s");
      require(s.interval > 0.0, p, "interval", "must be > 0 (a row every this many seconds)");
      s.from_time = p.number_in_or("from_time", 0.0, limits::kTime, "s", 0.0);
    } else if (s.type == "velocity_field") {
      read_velocity_field(p, s);
    } else if (want > 0) {
      const json& bs = p.array("balls");
      if (bs.size() != want) p.fail("balls", "a " + s.type + " probe takes " + std::to_string(want) + " ball id(s)");
      for (std::size_t k = 0; k < bs.size(); ++k) {
        const std::string bp = p.child_path("balls") + "[" + std::to_string(k) + "]";
        if (!bs[k].is_string()) throw CaseError(bp, "expected a ball id (string)");
        if (!ids.count(bs[k].get<std::string>())) throw CaseError(bp, "no ball with id \"" + bs[k].get<std::string>() + "\"");
        s.balls.push_back(bs[k].get<std::string>());
      }
      if (want == 2 && s.balls[0] == s.balls[1]) p.fail("balls", "a pair needs two different balls");
      if (s.type == "ball") s.from_time = p.number_in_or("from_time", 0.0, limits::kTime, "s", 0.0);
    } else if (s.type == "outflow") {
      if (!cfg.outflow.enabled) p.fail("type", "an outflow probe needs stages.outflow");
    } else if (!cfg.drops) {
      p.fail("type", "a drops probe needs a \"drops\" section");
    }
    p.finish();
    cfg.probes.push_back(std::move(s));
  }
}


}  // namespace silodem::case_keys
