#include "silodem/case/generate_keys.hpp"

#include <cmath>
#include <stdexcept>

#include "silodem/case/case_error.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/scene/packing_builder.hpp"

namespace silodem::case_keys {

using nlohmann::json;

void read_balls_from_state(const JsonReader& r, CaseConfig& cfg) {
  if (!r.has("state_file")) r.fail("", "expected an array of balls, or {\"state_file\": PATH}, found an object without state_file");
  const std::string file = r.string("state_file");
  r.finish();
  StateSnapshot s;
  try {
    s = read_state(file);
  } catch (const CaseError& e) {
    r.fail("state_file", e.what());
  }
  const std::string where = r.child_path("state_file") + " (" + file + ")";
  for (const auto& b : s.balls) {
    const auto bad = [&](const std::string& why) { throw CaseError(where, "ball \"" + b.id + "\": " + why); };
    if (b.id.empty()) bad("an empty id");
    if (!cfg.materials.count(b.material)) bad("no material named \"" + b.material + "\" in the case");
    if (!(b.radius >= limits::kRadiusMin && b.radius <= limits::kLength)) bad("radius out of range");
    if ((b.position.array().abs() > limits::kLength).any()) bad("a position beyond 1e4 m");
    if ((b.velocity.array().abs() > limits::kSpeed).any()) bad("a velocity beyond 1e6 m/s");
    if (b.fixed && (b.velocity.norm() > 0.0 || b.angular_velocity.norm() > 0.0)) bad("a fixed ball cannot move");
    if (!cfg.contact.rotation() && b.angular_velocity.norm() > 0.0)
      bad("spins, but the case has no tangential or rolling law (balls rotate only then)");
  }
  cfg.balls.insert(cfg.balls.end(), std::make_move_iterator(s.balls.begin()), std::make_move_iterator(s.balls.end()));
}

namespace {

double coordinate(const json& a, const std::string& path, std::size_t k) {
  return json_number_in(a[k], path + "[" + std::to_string(k) + "]", -limits::kLength, limits::kLength, "m");
}

PackingRegion read_region(const JsonReader& r) {
  PackingRegion g;
  const std::string shape = r.choice_or("shape", {"box", "cylinder", "silo"}, "");
  if (shape.empty()) r.fail("shape", "required: \"box\", \"cylinder\" or \"silo\"");
  if (shape == "box") {
    g.min = r.vec3_within("min", limits::kLength, "m");
    g.max = r.vec3_within("max", limits::kLength, "m");
    if (!(g.min.array() < g.max.array()).all()) r.fail("max", "must exceed min in every component");
  } else {
    g.shape = shape == "cylinder" ? PackingRegion::Shape::Cylinder : PackingRegion::Shape::Silo;
    const json& c = r.array("centre");
    if (c.size() != 2) r.fail("centre", "give the vertical axis as [x, y] in m");
    g.cx = coordinate(c, r.child_path("centre"), 0), g.cy = coordinate(c, r.child_path("centre"), 1);
    g.radius = r.number_in("radius", limits::kRadiusMin, limits::kLength, "m");
    std::tie(g.z_lo, g.z_hi) = r.range_in("z", -limits::kLength, limits::kLength, "m");
    if (!(g.z_hi > g.z_lo)) r.fail("z", "needs z[1] > z[0]");
    if (g.shape == PackingRegion::Shape::Silo) {
      g.outlet_radius = r.number_in("outlet_radius", 0.0, g.radius, "m");
      g.half_angle = r.number_in("half_angle_deg", 1.0, 89.0, "deg") * kPi / 180.0;
    }
  }
  r.finish();
  return g;
}

PackingSpec read_generator(const JsonReader& r, const CaseConfig& cfg, std::size_t index) {
  PackingSpec s;
  s.name = r.string("name");
  if (s.name.empty()) r.fail("name", "must not be empty");
  // Probes and stages find a wall's balls by the prefix "<wall>_": no grain may carry it.
  for (const auto& w : cfg.walls)
    if ((s.name + "_").rfind(w.name + "_", 0) == 0 || (w.name + "_").rfind(s.name + "_", 0) == 0)
      r.fail("name", "\"" + s.name + "\" and wall \"" + w.name + "\" would share the id prefix; rename one of them");
  s.kind = r.choice_or("type", {"lattice", "random"}, "");
  if (s.kind.empty()) r.fail("type", "required: \"lattice\" or \"random\"");
  s.material = r.string("material");
  if (!cfg.materials.count(s.material)) r.fail("material", "no material named \"" + s.material + "\"");
  if (r.raw("radius").is_array()) std::tie(s.r_min, s.r_max) = r.range_in("radius", limits::kRadiusMin, limits::kLength, "m");
  else s.r_min = s.r_max = r.number_in("radius", limits::kRadiusMin, limits::kLength, "m");
  s.region = read_region(r.object("region"));
  const long max_count = long(limits::kGeneratedBalls);
  s.count = r.has("count") ? r.integer_in_or("count", 1, max_count, 1) : -1;
  if (s.kind == "random" && s.count < 0) r.fail("count", "required for a random packing");
  s.spacing = s.kind == "lattice" ? r.number_in_or("spacing", 2.0 * s.r_max, limits::kLength, "m", 2.002 * s.r_max) : 0.0;
  s.clearance = r.number_in_or("clearance", 0.0, limits::kLength, "m", 0.0);
  if (r.has("velocity")) s.velocity = r.vec3_within("velocity", limits::kSpeed, "m/s");
  s.seed = std::uint64_t(
      r.integer_in_or("seed", 0, 1L << 53, long((cfg.seed + 15485863UL * (index + 1)) % (1UL << 53))));
  // A lattice without a count fills the region: bound its sites (the builder's own count along each
  // edge) before any is made.
  if (s.kind == "lattice" && s.count < 0) {
    Vec3 lo, hi;
    region_bounds(s.region, lo, hi);
    const Vec3 span = (hi - lo).array() - 2.0 * (s.r_max + s.clearance);
    const double sites = ((span / s.spacing).array().max(0.0).floor() + 1.0).prod();
    if (sites > limits::kGeneratedBalls)
      r.fail("spacing", "the region holds about " + std::to_string(long(sites)) + " lattice sites, more than " +
                            std::to_string(max_count) + "; give a count or a larger spacing");
  }
  r.finish();
  return s;
}

}  // namespace

void read_generators(const JsonReader& r, CaseConfig& cfg) {
  const json& gs = r.array("generate");
  for (std::size_t i = 0; i < gs.size(); ++i) {
    const JsonReader g(gs[i], r.child_path("generate") + "[" + std::to_string(i) + "]");
    const PackingSpec spec = read_generator(g, cfg, i);
    std::vector<BallSpec> balls;
    try {
      balls = build_packing(spec);
    } catch (const std::runtime_error& e) {
      g.fail("region", e.what());
    }
    cfg.balls.insert(cfg.balls.end(), std::make_move_iterator(balls.begin()), std::make_move_iterator(balls.end()));
  }
}

void resolve_state_file(json& j, const std::filesystem::path& case_file) {
  if (!j.is_object() || !j.contains("balls") || !j["balls"].is_object()) return;
  json& b = j["balls"];
  if (!b.contains("state_file") || !b["state_file"].is_string()) return;
  const std::filesystem::path p = b["state_file"].get<std::string>();
  if (p.is_relative()) b["state_file"] = (std::filesystem::absolute(case_file).parent_path() / p).lexically_normal().string();
}

}  // namespace silodem::case_keys
