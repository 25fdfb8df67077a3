#include "silodem/output/state_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>

#include "silodem/case/case_error.hpp"
#include "silodem/case/json_reader.hpp"
#include "silodem/output/checked_file.hpp"
#include "silodem/output/state_binary.hpp"

namespace silodem {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
json vec(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }
}  // namespace

StateSnapshot read_state_header(const JsonReader& r) {
  StateSnapshot s;
  s.case_name = r.string_or("case", "");
  s.step = r.integer("step");
  s.time = r.number("time");
  s.dt = r.number("dt");
  if (s.step < 0 || !(s.dt > 0.0)) r.fail("step", "needs step >= 0 and dt > 0");
  return s;
}

bool state_is_finite(const Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!p.x[i].allFinite() || !p.v[i].allFinite()) return false;
  return true;
}

void write_state(const fs::path& file, const CaseConfig& cfg, const Particles& p,
                 const std::vector<std::string>& material_names, long step, double t) {
  if (!state_is_finite(p)) throw std::logic_error("a non-finite state reached " + file.string());
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.tag[a] < p.tag[b]; });
  // Ball by ball into the text, not through one JSON tree of every ball: the tree took about
  // 1 KB a ball. nlohmann writes doubles with the shortest representation that reads back exactly.
  const json head = {{"format", "silodem-state/1"}, {"case", cfg.name}, {"step", step}, {"time", t}, {"dt", cfg.dt}};
  std::string text = head.dump(0);
  text.pop_back();  // the closing brace: the balls follow
  text += ",\n\"balls\": [";
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    json b = {{"id", p.id[i]},
              {"material", material_names.at(std::size_t(p.material[i]))},
              {"radius", p.r[i]},
              {"position", vec(p.x[i])}};
    if (p.fixed(i)) b["fixed"] = true;
    else b["velocity"] = vec(p.v[i]);
    if (p.rotating && !p.fixed(i)) b["angular_velocity"] = vec(p.w[i]);
    text += (k ? ",\n" : "\n") + b.dump();
  }
  text += "\n]}\n";
  write_file_checked(file, text);
}

void write_states(const fs::path& dir, const CaseConfig& cfg, const Particles& p,
                  const std::vector<std::string>& material_names, long step, double t) {
  write_state_binary(dir / "state.sds", cfg.name, cfg.dt, p, material_names, step, t);
  if (cfg.state_json) write_state(dir / "state.json", cfg, p, material_names, step, t);
}

std::string state_file_name(const CaseConfig& cfg) { return cfg.state_json ? "state.json" : "state.sds"; }

StateSnapshot read_state(const fs::path& file) {
  if (is_binary_state(file)) return read_state_binary(file);
  std::ifstream in(file);
  if (!in) throw CaseError(file.string(), "cannot read the state file");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw CaseError(file.string(), std::string("not valid JSON: ") + e.what());
  }
  const JsonReader r(j, file.string() + " $");
  if (r.string("format") != "silodem-state/1") r.fail("format", "expected \"silodem-state/1\"");
  StateSnapshot s = read_state_header(r);
  const json& bs = r.array("balls");
  for (std::size_t i = 0; i < bs.size(); ++i) {
    const JsonReader b(bs[i], r.child_path("balls") + "[" + std::to_string(i) + "]");
    BallSpec x;
    x.id = b.string("id");
    x.material = b.string("material");
    x.radius = b.number("radius");
    if (!(x.radius > 0.0)) b.fail("radius", "must be > 0");
    x.position = b.vec3("position");
    x.velocity = b.vec3_or("velocity", Vec3::Zero());
    x.angular_velocity = b.vec3_or("angular_velocity", Vec3::Zero());
    x.fixed = b.boolean_or("fixed", false);
    b.finish();
    s.balls.push_back(std::move(x));
  }
  r.finish();
  return s;
}

CaseConfig continuation(const CaseConfig& cfg, const StateSnapshot& s) {
  const std::string where = "state of case \"" + s.case_name + "\" at step " + std::to_string(s.step);
  if (std::abs(s.dt - cfg.dt) > 1e-12 * cfg.dt)
    throw CaseError(where, "time step " + std::to_string(s.dt) + " s differs from the case's " + std::to_string(cfg.dt) +
                               " s: a continuation must keep the step");
  if (double(s.step) * cfg.dt > cfg.duration + 0.5 * cfg.dt)
    throw CaseError(where, "starts after the case's duration");
  if (cfg.drops && cfg.drops->count > 0)
    throw CaseError(where, "the case drops balls (drops.count > 0); a state does not hold the feeder's progress");
  CaseConfig c = cfg;
  if (c.wall_reference.empty())
    for (const auto& w : cfg.walls)
      if (w.motion)
        for (const auto& b : cfg.balls)
          if (b.fixed && b.id.rfind(w.name + "_", 0) == 0) c.wall_reference.emplace_back(b.id, b.position);
  c.balls = s.balls;
  c.listed_balls = c.balls.size(), c.generated_balls = 0;
  for (const auto& b : c.balls)
    if (!c.materials.count(b.material)) throw CaseError(where, "ball \"" + b.id + "\" has material \"" + b.material +
                                                                   "\", which the case does not define");
  c.start_step = s.step;
  return c;
}

}  // namespace silodem
