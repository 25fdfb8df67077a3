#include "silodem/case/case_loader.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_set>

#include "silodem/case/breakage_keys.hpp"
#include "silodem/case/case_file.hpp"
#include "silodem/case/contact_keys.hpp"
#include "silodem/case/motion_keys.hpp"
#include "silodem/case/feasibility.hpp"
#include "silodem/case/generate_keys.hpp"
#include "silodem/case/planar_checks.hpp"
#include "silodem/case/vessel_keys.hpp"
#include "silodem/case/initial_contacts.hpp"
#include "silodem/case/json_reader.hpp"
#include "silodem/case/json_text.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/case/memory_estimate.hpp"
#include "silodem/case/path_name.hpp"
#include "silodem/case/probe_keys.hpp"
#include "silodem/case/surface_keys.hpp"
#include "silodem/contact/hertz_constants.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/contact/stiffest_pair.hpp"
#include "silodem/scene/wall_builders.hpp"

namespace silodem {

using nlohmann::json;

namespace {

using case_keys::positive;
using case_keys::read_contact_models;
using case_keys::read_friction;
using case_keys::read_hertz_material;
using case_keys::read_material_pairs;
using case_keys::refuse_unless;
using case_keys::require;


Material read_material(const JsonReader& r, const std::string& name, const ContactSpec& contact) {
  const bool clamp = contact.clamp;
  Material m;
  m.name = name;
  m.density = r.number_in("density", limits::kDensityMin, limits::kDensityMax, "kg/m^3");
  read_friction(r, m, contact);
  if (contact.normal == NormalModel::Hertz) return read_hertz_material(r, m, clamp);
  for (const char* key : {"youngs_modulus", "poisson_ratio"})
    if (r.has(key)) r.fail(key, "is read only with contact.normal \"hertz\"");
  const bool has_k = r.has("stiffness"), has_tc = r.has("contact_time");
  const bool has_c = r.has("damping"), has_z = r.has("damping_ratio"), has_e = r.has("restitution");
  if (has_k == has_tc) r.fail("", "give exactly one of \"stiffness\" (per-ball k_i, N/m) or \"contact_time\" (s)");
  if (int(has_c) + int(has_z) + int(has_e) != 1)
    r.fail("", "give exactly one of \"damping\" (per-ball c_i, N s/m), \"damping_ratio\" or \"restitution\"");
  if (has_k && has_c) {
    m.k = positive(r, "stiffness", limits::kStiffness, "N/m");
    m.c = r.number("damping");
    require(m.c >= 0.0, r, "damping", "must be >= 0");
    m.c = r.number_in("damping", 0.0, limits::kDamping, "N s/m");
    m.derived_from = "stiffness+damping";
    r.finish();
    return m;
  }
  // Derived constants refer to a pair of two equal balls of the reference radius.
  if (has_tc && has_c) r.fail("damping", "with \"contact_time\" give \"damping_ratio\" or \"restitution\", not \"damping\"");
  const double r_ref = r.number_in("reference_radius", limits::kRadiusMin, limits::kLength, "m");
  const double m_ref = m.density * 4.0 / 3.0 * kPi * r_ref * r_ref * r_ref;
  double zeta = 0.0;
  if (has_z) {
    zeta = r.number("damping_ratio");
    require(zeta >= 0.0 && (clamp || zeta < 1.0), r, "damping_ratio",
            clamp ? "must be >= 0" : "must be in [0, 1): an unclamped overdamped contact never ends");
    r.number_in("damping_ratio", 0.0, limits::kDampingRatio, "");
  } else if (has_c) {
    // stiffness + damping handled above; here only stiffness with damping can't happen.
  } else {
    const double e = r.number("restitution");
    require(e > 0.0 && e <= 1.0, r, "restitution", "must be in (0, 1]");
    zeta = contact::damping_ratio_for_restitution(e, clamp);
  }
  double k_pair = 0.0;
  if (has_k) {
    k_pair = 0.5 * positive(r, "stiffness", limits::kStiffness, "N/m");
    m.derived_from = has_z ? "stiffness+damping_ratio" : "stiffness+restitution";
  } else {
    const double t_c = r.number_in("contact_time", limits::kContactTimeMin, limits::kContactTimeMax, "s");
    k_pair = contact::pair_stiffness_for_duration(t_c, zeta, 0.5 * m_ref, clamp);
    m.derived_from = has_z ? "contact_time+damping_ratio" : "contact_time+restitution";
  }
  const auto bc = contact::ball_constants_from_pair(k_pair, zeta, m_ref);
  m.k = bc.k;
  m.c = bc.c;
  r.finish();
  return m;
}


BallSpec read_ball(const JsonReader& r, const CaseConfig& cfg) {
  BallSpec b;
  b.id = r.string("id");
  require(!b.id.empty(), r, "id", "must not be empty");
  require(b.id.find('\0') == std::string::npos, r, "id", "must not hold a NUL character");
  b.material = r.string("material");
  require(cfg.materials.count(b.material) == 1, r, "material", "no material named \"" + b.material + "\"");
  b.radius = r.number_in("radius", limits::kRadiusMin, limits::kLength, "m");
  b.position = r.vec3_within("position", limits::kLength, "m");
  if (r.has("velocity")) b.velocity = r.vec3_within("velocity", limits::kSpeed, "m/s");
  refuse_unless(cfg.contact.rotation(), r, "angular_velocity", "a tangential or rolling law (balls rotate only then)");
  if (r.has("angular_velocity")) b.angular_velocity = r.vec3_within("angular_velocity", limits::kSpinRate, "rad/s");
  b.fixed = r.boolean_or("fixed", false);
  require(!(b.fixed && b.angular_velocity.norm() > 0.0), r, "angular_velocity", "a fixed ball cannot spin");
  require(!(b.fixed && r.has("velocity") && b.velocity.norm() > 0.0), r, "velocity", "a fixed ball cannot move");
  r.finish();
  return b;
}

/// A wall of fixed balls (scene/wall_builders.hpp), expanded into the case's ball list.
WallSpec read_wall(const JsonReader& r, std::size_t index, CaseConfig& cfg) {
  WallSpec w;
  w.name = r.string("name");
  require(!w.name.empty() && w.name.find_first_of("/\\ ") == std::string::npos, r, "name",
          "must be a non-empty name without spaces or slashes");
  w.type = r.choice_or("type", {"cylinder", "disk", "cone", "tray", "drum"}, "");
  w.material = r.string("material");
  require(cfg.materials.count(w.material) == 1, r, "material", "no material named \"" + w.material + "\"");
  std::tie(w.r_min, w.r_max) = r.range("radius");
  require(w.r_min > 0.0, r, "radius", "radii must be > 0");
  r.range_in("radius", limits::kRadiusMin, limits::kLength, "m");
  w.spacing = positive(r, "spacing", limits::kLength, "m");
  // docs/model.md §3: the wall balls overlap each other; a net that does not overlap has holes.
  require(w.spacing < 2.0 * w.r_min, r, "spacing",
          "wall balls must overlap: spacing " + format_number(w.spacing) + " m is not below 2 r_min = " +
              format_number(2.0 * w.r_min) + " m");
  w.centre = r.vec3_within("centre", limits::kLength, "m");
  if (w.type == "tray") {
    case_keys::read_tray(r, w);
  } else {
  w.diameter = positive(r, "diameter", limits::kLength, "m");
  if (w.type == "drum") {
    case_keys::read_drum(r, w);
  } else {
  if (w.type != "disk") w.height = positive(r, "height", limits::kLength, "m");
  if (w.type == "cylinder" && r.has("hole_diameter")) r.fail("hole_diameter", "a cylinder has no outlet; put it in a disk or cone");
  w.hole_diameter = r.number_or("hole_diameter", 0.0);
  require(w.hole_diameter >= 0.0 && w.hole_diameter < w.diameter, r, "hole_diameter", "must be in [0, diameter)");
  if (w.type == "cone") require(w.hole_diameter > 0.0, r, "hole_diameter", "a hopper needs an outlet > 0");
  }
  }
  if (const auto m = r.opt_object("motion")) w.motion = case_keys::read_motion(*m);
  r.finish();
  // Counted with the balls already built, so that many walls cannot exhaust memory either.
  const double n = estimated_wall_balls(w) + double(cfg.balls.size());
  require(n <= limits::kWallBalls, r, "spacing",
          "the scene would need about " + format_number(std::round(n)) + " balls with this wall (at most " +
              format_number(limits::kWallBalls) + "): the spacing is too small for its size");
  for (auto& b : build_wall(w, cfg.seed + 7919 * (index + 1))) cfg.balls.push_back(std::move(b));
  return w;
}

DropSpec read_drops(const JsonReader& r, const CaseConfig& cfg) {
  DropSpec d;
  d.material = r.string("material");
  require(cfg.materials.count(d.material) == 1, r, "material", "no material named \"" + d.material + "\"");
  std::tie(d.r_min, d.r_max) = r.range("radius");
  require(d.r_min > 0.0, r, "radius", "radii must be > 0");
  r.range_in("radius", limits::kRadiusMin, limits::kLength, "m");
  d.z0 = r.number_in("z0", -limits::kLength, limits::kLength, "m");
  d.count = r.integer("count");
  require(d.count >= 0, r, "count", "must be >= 0");
  d.count = r.integer_in_or("count", 0, limits::kDropCount, 0);
  d.release = r.choice_or("placement", {"first_contact", "release"}, "first_contact") == "release";
  if (d.release) {
    require(!r.has("initial_velocity"), r, "initial_velocity",
            "a released drop starts at its release point with release_speed (placement \"release\"); omit "
            "initial_velocity");
    if (r.has("release_speed")) d.release_speed = r.number_in("release_speed", 0.0, limits::kSpeed, "m/s");
  } else {
    require(!r.has("release_speed"), r, "release_speed", "only with placement \"release\"");
  }
  d.free_fall_velocity = !d.release && r.choice_or("initial_velocity", {"free_fall", "zero"}, "free_fall") == "free_fall";
  d.interval_steps = r.integer_or("interval_steps", 1);
  require(d.interval_steps >= 1, r, "interval_steps", "must be >= 1");
  if (r.has("full_level")) {
    require(!d.release, r, "full_level",
            "released drops follow a sequence fixed in advance (placement \"release\"): their count ends it, not the fill height");
    d.full_level = r.number_in("full_level", -limits::kLength, limits::kLength, "m");
    require(d.full_level <= d.z0, r, "full_level", "must not be above the release height z0 (drops wait while the fill is above z0)");
  }
  if (r.has("positions")) {
    const json& ps = r.array("positions");
    require(!ps.empty(), r, "positions", "must not be empty (omit it for random positions)");
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::string p = r.child_path("positions") + "[" + std::to_string(i) + "]";
      if (!ps[i].is_array() || ps[i].size() != 2) throw CaseError(p, "expected [x0, y0]");
      d.positions.push_back({json_number_in(ps[i][0], p + "[0]", -limits::kLength, limits::kLength, "m"),
                             json_number_in(ps[i][1], p + "[1]", -limits::kLength, limits::kLength, "m")});
    }
    require(d.count <= long(d.positions.size()), r, "count", "larger than the number of explicit positions");
  } else {
    const JsonReader inlet = r.object("inlet");
    std::tie(d.x_min, d.x_max) = inlet.range_in("x", -limits::kLength, limits::kLength, "m");
    std::tie(d.y_min, d.y_max) = inlet.range_in("y", -limits::kLength, limits::kLength, "m");
    inlet.finish();
  }
  require(std::isnan(d.full_level) || d.positions.empty(), r, "full_level",
          "needs random release points (inlet): the fill height is measured over the inlet's columns");
  r.finish();
  return d;
}

void read_integrator(const JsonReader& r, IntegratorSpec& in) {
  const std::string s = r.choice_or("scheme", {"predictor_corrector", "velocity_verlet", "runge_kutta_midpoint"},
                                    kDefaultScheme == Scheme::VelocityVerlet ? "velocity_verlet" : "predictor_corrector");
  in.scheme = s == "velocity_verlet"         ? Scheme::VelocityVerlet
              : s == "runge_kutta_midpoint" ? Scheme::RungeKuttaMidpoint
                                            : Scheme::PredictorCorrector;
  in.viscosity = r.number_in_or("viscosity", 0.0, 1.0 / limits::kDtMin, "1/s", 0.0);
  if (in.scheme != Scheme::RungeKuttaMidpoint && r.has("viscosity"))
    r.fail("viscosity", "only runge_kutta_midpoint takes the artificial viscosity");
  if (in.scheme == Scheme::RungeKuttaMidpoint &&
      (r.has("max_corrector_passes") || r.has("corrector_stop") || r.has("dashpot_velocity")))
    r.fail("scheme", "runge_kutta_midpoint has no corrector and evaluates the dashpot at its own stages");
  // Range-checked as a long: narrowing first would let 2^32 + 5 pass as 5.
  in.max_corrector_passes = int(r.integer_in_or("max_corrector_passes", 1, 1000, 1));
  const std::string stop = r.choice_or("corrector_stop", {"fixed_point", "paper_literal", "relative"}, "fixed_point");
  in.corrector_stop = stop == "paper_literal" ? CorrectorStop::PaperLiteral
                      : stop == "relative"    ? CorrectorStop::Relative
                                              : CorrectorStop::FixedPoint;
  in.relative_tolerance = r.number_in_or("relative_tolerance", 1e-15, 1.0, "", 1e-5);
  if (r.has("relative_tolerance") && in.corrector_stop != CorrectorStop::Relative)
    r.fail("relative_tolerance", "only corrector_stop \"relative\" takes relative_tolerance (p_acc sets the others' tolerance)");
  in.p_acc = r.has("p_acc") ? positive(r, "p_acc", limits::kFactor, "") : 0.1;
  in.half_step_dashpot = r.choice_or("dashpot_velocity", {"predicted", "half_step"}, "predicted") == "half_step";
  if (in.scheme == Scheme::VelocityVerlet && (r.has("max_corrector_passes") || r.has("corrector_stop")))
    r.fail("scheme", "velocity_verlet has no corrector: remove max_corrector_passes/corrector_stop");
  if (in.scheme == Scheme::PredictorCorrector && r.has("dashpot_velocity"))
    r.fail("dashpot_velocity", "only velocity_verlet takes dashpot_velocity");
  r.finish();
}

/// A velocity_field probe's grid of rings and its sampling window.
}  // namespace

CaseConfig load_case(const json& j) {
  CaseConfig cfg;
  const JsonReader r(j, "$");
  check_case_copy_fits(j);
  cfg.source = j;
  const std::string format = r.string_or("format", "silodem-case/1");
  require(format == "silodem-case/1", r, "format", "unsupported format \"" + format + "\" (this build reads silodem-case/1)");
  cfg.name = r.string("name");
  require_path_name(cfg.name, r.child_path("name"));  // verify and compare write <out>/<name>/
  cfg.description = r.string_or("description", "");
  const long seed = r.integer_or("seed", 1);
  require(seed >= 0, r, "seed", "must be >= 0");
  cfg.seed = std::uint64_t(seed);
  if (r.has("gravity")) cfg.gravity = r.vec3_within("gravity", limits::kGravity, "m/s^2");
  cfg.dimension = int(r.integer_in_or("dimension", 2, 3, 3));
  if (r.choice_or("grain_inertia", {"sphere", "disc"}, "sphere") == "disc") {
    require(cfg.dimension == 2, r, "grain_inertia", "a disc's inertia (1/2 m r^2) needs \"dimension\": 2");
    cfg.inertia_factor = 0.5;
  }

  if (auto c = r.opt_object("contact")) {
    cfg.contact.clamp = c->boolean_or("clamp_tensile_force", false);
    cfg.contact.onset_correction = c->boolean_or("onset_correction", false);
    read_contact_models(*c, cfg.contact);
    if (auto coh = c->opt_object("cohesion")) {
      cfg.contact.cohesion = coh->boolean_or("enabled", true);
      cfg.contact.p_n = coh->has("p_N") ? positive(*coh, "p_N", limits::kFactor, "") : 0.1;
      coh->finish();
    }
    c->finish();
  }
  if (cfg.contact.cohesion && cfg.gravity.norm() == 0.0)
    r.fail("gravity", "cohesion (10) scales with |g|; it is undefined with zero gravity");

  const JsonReader mats = r.object("materials");
  if (j.at("materials").empty()) mats.fail("", "at least one material is required");
  for (auto it = j.at("materials").begin(); it != j.at("materials").end(); ++it) {
    const JsonReader m = mats.object(it.key());
    cfg.materials[it.key()] = read_material(m, it.key(), cfg.contact);
  }
  mats.finish();
  if (r.has("material_pairs")) read_material_pairs(r, cfg);

  std::unordered_set<std::string> ids;
  std::vector<std::size_t> wall_first;  // index of each wall's first ball in cfg.balls
  if (r.has("balls") && r.raw("balls").is_object()) {
    case_keys::read_balls_from_state(r.object("balls"), cfg);
    ids.reserve(2 * cfg.balls.size());
    for (const auto& b : cfg.balls)
      if (!ids.insert(b.id).second) throw CaseError(r.child_path("balls") + ".state_file", "duplicate ball id \"" + b.id + "\"");
  } else if (r.has("balls")) {
    const json& bs = r.array("balls");
    for (std::size_t i = 0; i < bs.size(); ++i) {
      const JsonReader b(bs[i], r.child_path("balls") + "[" + std::to_string(i) + "]");
      cfg.balls.push_back(read_ball(b, cfg));
      require(ids.insert(cfg.balls.back().id).second, b, "id", "duplicate ball id \"" + cfg.balls.back().id + "\"");
    }
  }
  cfg.listed_balls = cfg.balls.size();
  if (r.has("walls")) {
    const json& ws = r.array("walls");
    // Probes and stages find a wall's balls by the id prefix "<name>_": no name may shadow another.
    // A name that is not a string is left to read_wall, which names the error.
    const auto name_of = [](const json& w) -> std::optional<std::string> {
      if (w.is_object() && w.contains("name") && w["name"].is_string()) return w["name"].get<std::string>();
      return std::nullopt;
    };
    for (std::size_t i = 0; i < ws.size(); ++i)
      if (const auto name = name_of(ws[i])) {
        const std::string prefix = *name + "_";
        for (const auto& id : ids)
          if (id.rfind(prefix, 0) == 0)
            throw CaseError(r.child_path("walls") + "[" + std::to_string(i) + "].name",
                            "ball \"" + id + "\" would be taken for a ball of this wall; rename one of them");
        for (std::size_t w = 0; w < ws.size(); ++w)
          if (w != i && name_of(ws[w]).value_or("").rfind(prefix, 0) == 0)
            throw CaseError(r.child_path("walls") + "[" + std::to_string(w) + "].name",
                            "begins with another wall's name and \"_\"; rename one of them");
      }
    for (std::size_t i = 0; i < ws.size(); ++i) {
      const JsonReader w(ws[i], r.child_path("walls") + "[" + std::to_string(i) + "]");
      const std::size_t first = cfg.balls.size();
      wall_first.push_back(first);
      cfg.walls.push_back(read_wall(w, i, cfg));
      for (std::size_t k = first; k < cfg.balls.size(); ++k)
        require(ids.insert(cfg.balls[k].id).second, w, "name", "wall ball id \"" + cfg.balls[k].id + "\" is taken");
    }
  }
  const std::size_t generated_first = cfg.balls.size();
  if (r.has("generate")) {
    const std::size_t first = generated_first;
    case_keys::read_generators(r, cfg);
    ids.reserve(2 * cfg.balls.size());
    for (std::size_t k = first; k < cfg.balls.size(); ++k)
      if (!ids.insert(cfg.balls[k].id).second) r.fail("generate", "ball id \"" + cfg.balls[k].id + "\" is taken; rename the generator");
    cfg.generated_balls = cfg.balls.size() - first;
  }
  if (r.has("surfaces")) case_keys::read_surfaces(r, cfg);
  if (auto d = r.opt_object("drops")) {
    cfg.drops = read_drops(*d, cfg);
    // Algorithm 2 falls along −z (docs/model.md §1 Reading: z up).
    if (!(cfg.gravity.z() < 0.0 && cfg.gravity.x() == 0.0 && cfg.gravity.y() == 0.0))
      r.fail("gravity", "drops fall along -z: gravity must be [0, 0, -g] with g > 0");
    // No room: the fill already reaches the release height, so no drop could ever be made.
    for (const auto& b : cfg.balls)
      if (!b.fixed && b.position.z() >= cfg.drops->z0 && cfg.drops->count > 0)
        d->fail("z0", "no room: mobile ball \"" + b.id + "\" is already at or above the release height z0 = " +
                          std::to_string(cfg.drops->z0) + " m, and drops wait until the fill is below it");
  }
  if (auto b = r.opt_object("breakage")) cfg.breakage = case_keys::read_breakage(*b, cfg);
  bool any_mobile = cfg.drops && cfg.drops->count > 0;
  for (const auto& b : cfg.balls) any_mobile = any_mobile || !b.fixed;
  if (!any_mobile) r.fail("balls", "the scene has no mobile ball and no drops: nothing to simulate");
  check_wall_geometry(cfg, r.child_path("walls"));

  if (auto st = r.opt_object("stages")) {
    if (auto o = st->opt_object("outflow")) {
      cfg.outflow.enabled = true;
      cfg.outflow.below_z = o->number_in("below_z", -limits::kLength, limits::kLength, "m");
      cfg.outflow.recycle = o->choice_or("mode", {"recycle", "remove"}, "recycle") == "recycle";
      cfg.outflow.every_steps = o->integer_in_or("every_steps", 1, 1000000, 1);
      if (cfg.outflow.recycle && (!cfg.drops || !cfg.drops->positions.empty()))
        o->fail("mode", "recycling re-drops balls at random inlet points: it needs a \"drops\" section with an inlet");
      if (cfg.outflow.recycle && cfg.drops && cfg.drops->release)
        o->fail("mode", "recycling places leavers at their first contact (Algorithm 2); released drops (placement "
                        "\"release\") follow a fixed sequence: use mode \"remove\"");
      o->finish();
    }
    if (st->has("events")) {
      const json& es = st->array("events");
      for (std::size_t i = 0; i < es.size(); ++i) {
        const JsonReader e(es[i], st->child_path("events") + "[" + std::to_string(i) + "]");
        StageEvent ev;
        ev.time = e.number("time");
        require(ev.time >= 0.0, e, "time", "must be >= 0");
        e.number_in("time", 0.0, limits::kTime, "s");
        ev.type = e.choice_or("type", {"open_outlet", "close_outlet", "move_wall"}, "");
        if (ev.type == "move_wall" && e.has("ball")) {
          // A listed fixed ball moved on its own (a floor ball under a single grain).
          if (e.has("wall")) e.fail("ball", "give \"wall\" or \"ball\", not both");
          ev.ball = e.string("ball");
          bool fixed_ball = false;
          for (const auto& b : cfg.balls) fixed_ball = fixed_ball || (b.id == ev.ball && b.fixed);
          if (!fixed_ball) e.fail("ball", "no fixed ball with id \"" + ev.ball + "\" among the listed balls");
          ev.velocity = e.vec3_within("velocity", limits::kSpeed, "m/s");
        } else if (ev.type == "open_outlet" || ev.type == "move_wall") {
          ev.wall = e.string("wall");
          if (ev.type == "open_outlet")
            ev.release_mobile = e.choice_or("release", {"remove", "mobile"}, "remove") == "mobile";
          else
            ev.velocity = e.vec3_within("velocity", limits::kSpeed, "m/s");
          bool found = false;
          for (const auto& w : cfg.walls) {
            found = found || w.name == ev.wall;
            if (w.name == ev.wall && w.motion && ev.type == "move_wall")
              e.fail("wall", "wall \"" + ev.wall + "\" follows its \"motion\" law; a move_wall event cannot move it too");
          }
          if (!found) e.fail("wall", "no wall named \"" + ev.wall + "\"");
        } else {
          ev.centre = e.vec3_within("centre", limits::kLength, "m");
          ev.diameter = positive(e, "diameter", limits::kLength, "m");
          ev.thickness = positive(e, "thickness", limits::kLength, "m");
        }
        e.finish();
        cfg.events.push_back(ev);
      }
    }
    st->finish();
  }
  cfg.integrator.scheme = kDefaultScheme;
  if (auto in = r.opt_object("integrator")) {
    read_integrator(*in, cfg.integrator);
    // A moving wall is placed at the step's end before the step (motion/wall_motion.hpp): the
    // midpoint stage would see it there, not at t + Δt/2.
    bool moving = false;
    for (const auto& w : cfg.walls) moving = moving || w.motion.has_value();
    for (const auto& ev : cfg.events) moving = moving || ev.type == "move_wall";
    if (moving && cfg.integrator.scheme == Scheme::RungeKuttaMidpoint)
      in->fail("scheme", "runge_kutta_midpoint does not take walls in motion (\"motion\" or move_wall) yet: its "
                         "half-step evaluation would see them at the step's end");
  }

  const JsonReader t = r.object("time");
  if (t.has("dt") && t.has("dt_per_contact_time"))
    t.fail("", "give at most one of \"dt\" (s) or \"dt_per_contact_time\" (fraction of the stiffest pair's t_c)");
  cfg.duration = positive(t, "duration", limits::kTime, "s");
  if (t.has("dt")) {
    cfg.dt = positive(t, "dt", limits::kTime, "s");
  } else if (cfg.contact.normal == NormalModel::Hertz) {
    t.fail("dt", "a Hertz contact's duration depends on the impact speed, so no step follows from the materials alone: "
                 "give \"dt\" (docs/case-format.md \"Friction\")");
  } else {
    cfg.dt_per_contact_time =
        t.has("dt_per_contact_time") ? positive(t, "dt_per_contact_time", 1.0, "") : kDefaultDtPerContactTime;
    const std::string defaulted = t.has("dt_per_contact_time") ? "" : " (no step given: the default is " +
        format_number(kDefaultDtPerContactTime) + " of the stiffest pair's contact time)";
    const auto sp = stiffest_pair(cfg);
    if (!sp) t.fail("dt_per_contact_time", "the scene forms no contact pair; give \"dt\" instead" + defaulted);
    if (!std::isfinite(sp->behaviour.duration))
      t.fail("dt_per_contact_time", "the stiffest pair (" + sp->description + ") is overdamped and never ends its contact");
    cfg.dt = *cfg.dt_per_contact_time * sp->behaviour.duration;
  }
  const std::string dt_key = t.has("dt") ? "dt" : "dt_per_contact_time";
  require(cfg.dt < cfg.duration, t, dt_key,
          "the time step (" + format_number(cfg.dt) + " s) is not shorter than the duration");
  require(cfg.duration / cfg.dt <= limits::kSteps, t, dt_key,
          "the run would take " + format_number(std::ceil(cfg.duration / cfg.dt)) + " steps (at most " +
              format_number(limits::kSteps) + ")");
  t.finish();
  check_time_step(cfg, t.child_path(dt_key));

  if (auto gd = r.opt_object("guards")) {
    cfg.guards.max_overlap_ratio = gd->number_in_or("max_overlap_ratio", 1e-6, 2.0, "", 0.5);
    cfg.guards.max_travel_ratio = gd->number_in_or("max_travel_ratio", 1e-6, 2.0, "", 0.5);
    cfg.guards.max_energy_drift = gd->number_in_or("max_energy_drift", 1e-6, limits::kFactor, "", 0.5);
    cfg.guards.domain_margin = gd->number_in_or("domain_margin", 0.0, limits::kLength, "m", 1.0);
    cfg.guards.max_steps = gd->integer_or("max_steps", 0);
    require(cfg.guards.max_steps >= 0, *gd, "max_steps", "must be >= 0 (0: no limit)");
    cfg.guards.max_wall_seconds = gd->number_in_or("max_wall_seconds", 0.0, 1e9, "s", 0.0);
    gd->finish();
  }
  {
    // The JSON path a ball came from: its entry in "balls" (or the state file), the wall that built
    // it, or the generators.
    const std::size_t listed = wall_first.empty() ? generated_first : wall_first.front();
    const bool from_state = r.has("balls") && r.raw("balls").is_object();
    const auto path_of = [&](std::size_t i) {
      if (i >= generated_first) return r.child_path("generate") + " (ball \"" + cfg.balls[i].id + "\")";
      if (i < listed && from_state) return r.child_path("balls") + ".state_file (ball \"" + cfg.balls[i].id + "\")";
      if (i < listed) return r.child_path("balls") + "[" + std::to_string(i) + "]";
      const auto w = std::size_t(std::upper_bound(wall_first.begin(), wall_first.end(), i) - wall_first.begin()) - 1;
      return r.child_path("walls") + "[" + std::to_string(w) + "]";
    };
    check_initial_contacts(cfg, path_of);
    check_initial_travel(cfg, path_of, r.child_path("drops") + ".release_speed");
    case_keys::check_surface_overlaps(cfg, r.child_path("surfaces"));
  }
  if (auto ck = r.opt_object("checkpoint")) {
    cfg.checkpoint.interval_steps = ck->integer_or("interval_steps", 0);
    require(cfg.checkpoint.interval_steps >= 0, *ck, "interval_steps", "must be >= 0 (0: not by steps)");
    cfg.checkpoint.interval_seconds = ck->number_in_or("interval_seconds", 0.0, 1e9, "s", 0.0);
    const long keep = ck->integer_or("keep", 2);
    require(keep >= 1 && keep <= 100, *ck, "keep", "must be 1 to 100");
    cfg.checkpoint.keep = int(keep);
    ck->finish();  // a misspelt interval is named as such, not as a missing one
    if (!cfg.checkpoint.enabled()) ck->fail("", "needs interval_steps or interval_seconds (> 0)");
  }
  if (auto e = r.opt_object("equilibrium")) {
    cfg.equilibrium.enabled = e->boolean_or("enabled", true);
    cfg.equilibrium.test = e->choice_or("test", {"forces_and_kinetic", "paper_literal"}, "forces_and_kinetic") ==
                                   "paper_literal"
                               ? EquilibriumTest::PaperLiteral
                               : EquilibriumTest::ForcesAndKinetic;
    if (cfg.equilibrium.test == EquilibriumTest::PaperLiteral && e->has("p_k"))
      e->fail("p_k", "the paper-literal test has no kinetic part; p_k is for test \"forces_and_kinetic\"");
    if (e->has("p_k")) cfg.equilibrium.p_k = positive(*e, "p_k", 1.0, "");
    cfg.equilibrium.p_f = e->number_or("p_f", 0.1);
    cfg.equilibrium.p_ft = e->number_or("p_ft", 0.01);
    cfg.equilibrium.check_interval_steps = e->integer_or("check_interval_steps", 1);
    cfg.equilibrium.min_time = e->number_or("min_time", 0.0);
    require(cfg.equilibrium.p_f > 0.0, *e, "p_f", "must be > 0");
    require(cfg.equilibrium.p_ft > 0.0, *e, "p_ft", "must be > 0");
    require(cfg.equilibrium.check_interval_steps >= 1, *e, "check_interval_steps", "must be >= 1");
    require(cfg.equilibrium.min_time >= 0.0, *e, "min_time", "must be >= 0");
    e->number_in_or("p_f", 0.0, limits::kFactor, "", 0.0);
    e->number_in_or("p_ft", 0.0, limits::kFactor, "", 0.0);
    e->number_in_or("min_time", 0.0, limits::kTime, "s", 0.0);
    if (cfg.gravity.norm() == 0.0) e->fail("", "the stop tests (27)-(29) are relative to weights: they need gravity");
    e->finish();
  }

  if (auto n = r.opt_object("neighbour")) {
    cfg.skin = n->number_or("skin", 0.0);
    require(cfg.skin >= 0.0, *n, "skin", "must be >= 0");
    n->number_in_or("skin", 0.0, limits::kLength, "m", 0.0);
    cfg.sort_interval_steps = n->integer_or("sort_interval_steps", kDefaultSortIntervalSteps);
    require(cfg.sort_interval_steps >= 0, *n, "sort_interval_steps", "must be >= 0 (0: never renumber)");
    n->finish();
  }

  if (auto o = r.opt_object("output")) {
    cfg.series_interval = o->number_or("series_interval", 0.0);
    require(cfg.series_interval >= 0.0, *o, "series_interval", "must be >= 0");
    o->number_in_or("series_interval", 0.0, limits::kTime, "s", 0.0);
    cfg.dump_interval_steps = o->integer_or("dump_interval_steps", 0);
    require(cfg.dump_interval_steps >= 0, *o, "dump_interval_steps", "must be >= 0 (0: no dumps)");
    cfg.state_json = o->boolean_or("state_json", true);
    cfg.vtk_interval_steps = o->integer_or("vtk_interval_steps", 0);
    cfg.vtk_float64 = o->choice_or("vtk_precision", {"float32", "float64"}, "float32") == "float64";
    require(cfg.vtk_interval_steps >= 0, *o, "vtk_interval_steps", "must be >= 0 (0: no VTK snapshots)");
    if (o->has("probes")) case_keys::read_probes(*o, cfg);
    o->finish();
  }
  if (r.has("verify")) cfg.verify = r.raw("verify");
  if (r.has("compare")) (void)r.raw("compare");  // read by `silodem compare` (harness/compare.cpp)
  r.finish();
  check_planar(cfg);
  check_run_memory(cfg, run_memory_limit());  // every count accepted is one the run can hold
  return cfg;
}

CaseConfig load_case_file(const std::filesystem::path& file) { return load_case(read_case_json(file)); }

json read_case_json(const std::filesystem::path& file) {
  json j = parse_case_text(read_case_text(file), file.string());
  case_keys::resolve_state_file(j, file);
  return j;
}

}  // namespace silodem
