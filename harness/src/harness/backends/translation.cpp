#include "harness/backends/translation.hpp"

#include <cctype>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "silodem/contact/pair_constants.hpp"
#include "silodem/scene/scene_builder.hpp"

namespace harness {

using silodem::CaseConfig;

double Translation::pair_k(int a, int b) const {
  return silodem::contact::series(types[std::size_t(a - 1)].k, types[std::size_t(b - 1)].k);
}
double Translation::pair_c(int a, int b) const {
  return silodem::contact::series(types[std::size_t(a - 1)].c, types[std::size_t(b - 1)].c);
}

const silodem::contact::PairParams& Translation::pair(int a, int b) const {
  return pairs.at(types[std::size_t(a - 1)].material, types[std::size_t(b - 1)].material);
}

std::set<double> Translation::type_radii(int type) const {
  std::set<double> radii;
  for (const auto& b : balls)
    if (b.type == type) radii.insert(b.radius);
  for (const auto& ev : events)
    if (ev.type == "insert" && ev.ball.type == type) radii.insert(ev.ball.radius);
  return radii;
}

std::size_t Translation::type_count(int type) const {
  std::size_t n = 0;
  for (const auto& b : balls) n += b.type == type;
  for (const auto& ev : events) n += ev.type == "insert" && ev.ball.type == type;
  return n;
}

const TranslatedBall* Translation::ball_of_type(int type) const {
  for (const auto& b : balls)
    if (b.type == type) return &b;
  for (const auto& ev : events)
    if (ev.type == "insert" && ev.ball.type == type) return &ev.ball;
  return nullptr;
}

bool Translation::can_touch(int a, int b) const {
  if (types[std::size_t(a - 1)].fixed && types[std::size_t(b - 1)].fixed) return false;
  return a != b ? type_count(a) > 0 && type_count(b) > 0 : type_count(a) > 1;
}

double case_skin(const CaseConfig& cfg) {
  if (cfg.skin > 0.0) return cfg.skin;
  double r_min = INFINITY;
  for (const auto& b : cfg.balls) r_min = std::min(r_min, b.radius);
  if (cfg.drops) r_min = std::min(r_min, cfg.drops->r_min);
  return 0.2 * r_min;  // as run/simulation.cpp
}

Translation translate(const CaseConfig& cfg, std::string& reason) {
  Translation t;
  reason.clear();
  t.start_step = cfg.start_step;
  t.steps = long(std::ceil(cfg.duration / cfg.dt - 1e-9));
  t.skin = case_skin(cfg);
  t.pairs = silodem::contact::pair_table(cfg);
  if (cfg.contact.normal == silodem::NormalModel::Hertz || cfg.contact.rolling == silodem::RollingModel::Spring)
    t.wall_density_factor = 1e12;
  auto type_of = [&](const std::string& material, bool fixed) {
    for (std::size_t i = 0; i < t.types.size(); ++i)
      if (t.types[i].material == material && t.types[i].fixed == fixed) return int(i + 1);
    const auto& m = cfg.materials.at(material);
    t.types.push_back({material, fixed, m.k, m.c, m.density});
    return int(t.types.size());
  };
  std::int64_t tag = 0;
  for (const auto& b : cfg.balls) {
    const auto& m = cfg.materials.at(b.material);
    t.balls.push_back({++tag, b.id, type_of(b.material, b.fixed), b.radius, m.density,
                       silodem::sphere_mass(m.density, b.radius), b.fixed, b.position, b.velocity, b.angular_velocity});
  }
  if (cfg.outflow.enabled) {
    if (cfg.outflow.recycle) {
      reason = "recycling leavers as analytic drops at the top (Algorithm 2) has no equivalent; use outflow "
               "\"mode\": \"remove\"";
      return t;
    }
    if (cfg.outflow.every_steps < kMinOutflowEvery) {
      reason = "stages.outflow.every_steps = " + std::to_string(cfg.outflow.every_steps) +
               ": the reference codes delete leavers periodically (fix evaporate, delete_atoms between run "
               "segments), which this often costs 10x the run or more; set every_steps >= " +
               std::to_string(kMinOutflowEvery) + " so that every code removes leavers on the same steps";
      return t;
    }
    t.outflow_below_z = cfg.outflow.below_z;
    t.outflow_every_steps = cfg.outflow.every_steps;
  }
  for (const auto& w : cfg.walls) {
    if (!w.motion) continue;
    const silodem::MotionLaw& law = *w.motion;
    if (cfg.start_step > 0) {
      reason = "wall \"" + w.name + "\" moves by a law: a continuation of it is not translated (the codes would "
               "take the state's places as the law's origin)";
      return t;
    }
    TranslatedMotion m{w.name, "law_" + w.name, {}, law};
    for (char& ch : m.group)
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    for (const auto& b : t.balls)
      if (b.fixed && b.id.rfind(w.name + "_", 0) == 0) m.tags.push_back(b.tag);
    t.motions.push_back(std::move(m));
  }
  std::vector<silodem::StageEvent> events = cfg.events;
  std::stable_sort(events.begin(), events.end(), [](const auto& a, const auto& b) { return a.time < b.time; });
  std::map<std::string, TranslatedEvent> motion_before_start;  // a continuation's walls still moving
  std::set<std::string> moving;                                // motions set by an event already translated
  for (const auto& ev : events) {
    // run/stages.cpp applies an event at the top of the first step s with s·dt reaching its time.
    const long step = std::max(0L, long(std::ceil((ev.time - 1e-15) / cfg.dt - 1e-9)));
    TranslatedEvent te{step, ev.type, {}, ev.centre, ev.diameter, ev.thickness};
    if (ev.type == "move_wall") {
      te.velocity = ev.velocity;
      te.motion = "wall_" + (ev.ball.empty() ? ev.wall : ev.ball);
      for (const auto& b : t.balls)
        if (b.fixed && ev.names(b.id)) te.tags.push_back(b.tag);
      if (step < cfg.start_step) {  // ran before the state: its velocity is set again at the start
        te.step = cfg.start_step;
        motion_before_start[te.motion] = te;
        continue;
      }
      te.moved_before = moving.count(te.motion) > 0 || motion_before_start.count(te.motion) > 0;
      moving.insert(te.motion);
    }
    if (step < cfg.start_step) continue;  // ran before the state a continuation starts from
    if (ev.type == "open_outlet") {
      if (ev.release_mobile) {
        reason = "setting overlapping gate balls free (open_outlet \"release\": \"mobile\") is not translated; "
                 "use the default release \"remove\"";
        return t;
      }
      for (const auto& b : t.balls)
        if (b.fixed && b.id.rfind(ev.wall + "_", 0) == 0) te.tags.push_back(b.tag);
    }
    t.events.push_back(std::move(te));
  }
  // The walls a continuation finds moving, first at its start (the state holds where, not how fast).
  std::vector<TranslatedEvent> replay;
  for (auto& [name, te] : motion_before_start) replay.push_back(te);
  t.events.insert(t.events.begin(), replay.begin(), replay.end());
  if (!cfg.drops || cfg.drops->count == 0) return t;
  if (cfg.drops->release && cfg.start_step > 0) {
    reason = "released drops are translated from the first step only, not into a continuation";
    return t;
  }
  if (cfg.drops->release && cfg.outflow.enabled) {
    reason = "released drops together with outflow are not translated: LAMMPS numbers a created ball after the "
             "largest tag present, which deletions change, so the codes' tags would part";
    return t;
  }
  if (!cfg.drops->release && cfg.drops->count > 1) {
    reason = "timed analytic drops (Algorithm 2, one every interval_steps) have no equivalent; only a single "
             "drop placed before the first step is translated";
    return t;
  }
  // The drops every code receives are the solver's own feeder's, on the scene as built.
  silodem::Scene scene = silodem::build_scene(cfg);
  const auto& m = cfg.materials.at(cfg.drops->material);
  silodem::DropFeeder feeder(*cfg.drops, m, scene.material_index(m.name), cfg.gravity, cfg.seed,
                             silodem::drop_tag(cfg, 0));
  const auto drop_ball = [&](const silodem::DropRecord& rec) {
    return TranslatedBall{silodem::drop_tag(cfg, rec.index), "drop" + std::to_string(rec.index), type_of(m.name, false),
                          rec.r, m.density, silodem::sphere_mass(m.density, rec.r), false, rec.x, rec.v};
  };
  if (cfg.drops->release) {
    // Attempt k at the top of step k·interval, as insert events.
    for (const auto& rec : feeder.planned_releases()) {
      const long step = rec.index * cfg.drops->interval_steps;
      if (step >= t.steps) break;  // the run ends before this attempt
      TranslatedEvent te;
      te.step = step;
      te.type = "insert";
      te.ball = drop_ball(rec);
      t.events.push_back(std::move(te));
    }
    // Stage events first at a shared step, then the drop attempt (run/simulation.cpp's order).
    std::stable_sort(t.events.begin(), t.events.end(), [](const auto& a, const auto& b) { return a.step < b.step; });
  } else if (auto rec = feeder.maybe_drop(scene.particles, 0, 0.0)) {
    // The same first-contact placement the solver makes at step 0.
    t.drops.push_back(*rec);
    if (rec->outcome == "placed") t.balls.push_back(drop_ball(*rec));
  }
  return t;
}

}  // namespace harness
