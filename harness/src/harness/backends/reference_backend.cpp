#include "harness/backends/reference_backend.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <iomanip>

#include "harness/backends/planar_frame.hpp"
#include "harness/backends/subprocess.hpp"
#include "harness/trace/reconstruct.hpp"
#include "silodem/output/checked_file.hpp"
#include "silodem/output/result_dir.hpp"

namespace harness {

namespace fs = std::filesystem;
using nlohmann::json;

long dump_interval(const silodem::CaseConfig& cfg) { return std::max(1L, cfg.dump_interval_steps); }

std::string ReferenceBackend::not_representable(const silodem::CaseConfig& cfg) const {
  if (cfg.contact.cohesion)
    return "no linear tensile spring acting only while separating, cut off at delta_c (docs/reference-codes.md)";
  if (cfg.contact.onset_correction)
    return "no correction of the dashpot impulse in the step of first touch or separation (silodem's onset_correction)";
  if (cfg.integrator.scheme != silodem::Scheme::VelocityVerlet || !cfg.integrator.half_step_dashpot)
    return "integrates by velocity Verlet/leapfrog with the dashpot at the half-step velocity only; the case asks "
           "for another scheme";
  if (cfg.breakage)
    return "no breakage model: seed 003's energy-based breakage (docs/model.md §14) replaces grains by fragments; "
           "none of LAMMPS, LIGGGHTS or YADE has it (docs/reference-codes.md)";
  if (cfg.equilibrium.enabled)
    return "the stop tests (27)-(29) end only silodem's run; give every code the same duration (disable "
           "\"equilibrium\" in the compare base)";
  for (const auto& s : cfg.surfaces) {
    if (!s.vertical())
      return "surface \"" + s.name + "\" has a non-vertical axis, which is not translated for the reference codes yet "
             "(issue 30)";
    if (s.angular_speed != 0.0)
      return "surface \"" + s.name + "\" spins about its axis, which is not translated for the reference codes yet "
             "(LAMMPS fix wall/gran shear, LIGGGHTS move/mesh rotate: issue 30)";
  }
  for (const auto& p : cfg.probes)
    if (p.type == "wall_load" && std::none_of(cfg.walls.begin(), cfg.walls.end(), [&](const auto& w) { return w.name == p.wall; }))
      return "wall_load probe \"" + p.name + "\" is on a smooth surface, which the reference codes' results do not "
             "give yet (issue 30)";
  std::string reason;
  const Translation tr = translation(cfg, reason);
  if (!reason.empty()) return reason;
  return code_limits(cfg, tr);
}

Translation ReferenceBackend::translation(const silodem::CaseConfig& cfg, std::string& reason) const {
  Translation tr = translate(cfg, reason);
  const silodem::Mat3 q = frame(cfg);
  return q.isIdentity() ? tr : in_frame(std::move(tr), q);
}

BackendResult ReferenceBackend::run(const silodem::CaseConfig& cfg, const fs::path& dir_in, double time_limit_s) const {
  // The code runs in its own work directory: every path handed to it must be absolute.
  const fs::path dir = fs::absolute(dir_in).lexically_normal();
  std::string reason;
  const Translation tr = translation(cfg, reason);
  if (!reason.empty()) return {BackendResult::Status::NotRepresentable, reason, {}};
  const fs::path tmp = dir.string() + ".partial-" + std::to_string(::getpid());
  silodem::check_output_dir(dir, {}, "a reference code's result directory");
  for (const auto& said : silodem::clean_stale_partials(dir)) std::fprintf(stderr, "[%s] %s\n", cfg.name.c_str(), said.c_str());
  silodem::remove_marked(tmp);
  std::error_code ec;
  fs::create_directories(tmp, ec);
  if (ec) throw silodem::WriteError(tmp, "cannot create the directory: " + ec.message());
  silodem::write_marker(tmp, "reference-run", "partial");
  const Input in = write_input(cfg, tr);
  for (const auto& [name, content] : in.files) silodem::write_file_checked(tmp / name, content);
  std::vector<std::string> argv = launch_prefix();
  argv.insert(argv.end(), in.argv.begin(), in.argv.end());
  std::vector<std::string> env = in.env;
  // Open MPI refuses to start as root without these (containers, CI); nothing changes otherwise.
  if (parallel_.ranks > 1) env.insert(env.end(), {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"});
  const ProcessOutcome po = run_process(argv, env, tmp, tmp / "log.txt", time_limit_s);
  std::string command;
  for (const auto& a : argv) command += (command.empty() ? "" : " ") + a;
  json meta = {{"code", code()},
               {"code_version", version(tmp / "log.txt")},
               {"input", in.main_file},
               {"command", command},
               {"ranks", parallel_.ranks},
               {"run", {{"wall_seconds", po.wall_seconds}, {"exit_status", po.exit_status}}}};
  const auto finish = [&](BackendResult::Status st, const std::string& why) {
    silodem::publish(tmp, dir, st == BackendResult::Status::Ran ? "complete" : "failed");
    return BackendResult{st, why, dir};
  };
  if (po.exit_status != 0 || !fs::exists(tmp / "dump.txt")) {
    const std::string why = (po.timed_out() ? "timed out after " + std::to_string(int(time_limit_s)) + " s"
                                            : "exit status " + std::to_string(po.exit_status)) +
                            "; log tail:\n" + tail(tmp / "log.txt", 15);
    meta["status"] = "failed";
    meta["error"] = why;
    meta["case"] = cfg.name;
    silodem::write_file_checked(tmp / "summary.json", meta.dump(2) + "\n");
    return finish(BackendResult::Status::Failed, why);
  }
  try {
    reconstruct_result(cfg, tr, tmp / "dump.txt", tmp, meta);
  } catch (const std::exception& e) {
    meta["status"] = "failed";
    meta["case"] = cfg.name;
    meta["error"] = std::string("could not read its output: ") + e.what();
    silodem::write_file_checked(tmp / "summary.json", meta.dump(2) + "\n");
    return finish(BackendResult::Status::Failed, meta["error"]);
  }
  fs::remove(tmp / "dump.txt");  // large; the result files hold what was read from it (summary: reconstructed_from)
  return finish(BackendResult::Status::Ran, "");
}

std::vector<std::string> ReferenceBackend::launch_prefix() const {
  if (parallel_.ranks <= 1) return {};
  const std::string n = std::to_string(parallel_.ranks);
  if (parallel_.launcher == "srun") return {"srun", "-n", n, "--cpus-per-task=1"};
  return {"mpirun", "-np", n};
}

std::string ReferenceBackend::set_mpi_parallel(const Parallel& p) {
  if (p.ranks < 1) return "the rank count must be at least 1";
  if (p.launcher != "mpirun" && p.launcher != "srun") return "unknown launcher \"" + p.launcher + "\" (mpirun or srun)";
  if (p.ranks > 1 && find_on_path(p.launcher).empty()) return p.launcher + " not found on PATH";
  parallel_ = p;
  return "";
}

std::string ReferenceBackend::decomposition(const silodem::CaseConfig& cfg) const {
  if (parallel_.ranks <= 1) return "";
  return cfg.dimension == 2 ? "processors * 1 1\n" : "processors * * 1\n";
}

std::string full_precision(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

TypeGroups lammps_type_groups(const Translation& tr) {
  TypeGroups g;
  const std::size_t n = tr.types.size();
  for (std::size_t t = 0; t < n; ++t) (tr.types[t].fixed ? g.wall : g.mobile) += " " + std::to_string(t + 1);
  // Wall balls overlap each other by design: their pairs must never be computed.
  for (std::size_t a = 1; a <= n; ++a)
    for (std::size_t b = a; b <= n; ++b)
      if (tr.types[a - 1].fixed && tr.types[b - 1].fixed)
        g.exclusions += " exclude type " + std::to_string(a) + " " + std::to_string(b);
  return g;
}

namespace {

/// "1:40 57 60:61": LAMMPS/LIGGGHTS group-by-id ranges for sorted tags.
std::string id_ranges(std::vector<std::int64_t> tags) {
  std::sort(tags.begin(), tags.end());
  std::string s;
  for (std::size_t i = 0; i < tags.size();) {
    std::size_t j = i;
    while (j + 1 < tags.size() && tags[j + 1] == tags[j] + 1) ++j;
    s += " " + std::to_string(tags[i]) + (j > i ? ":" + std::to_string(tags[j]) : "");
    i = j + 1;
  }
  return s;
}

/// The commands of one stage event (run/stages.cpp), between two runs.
std::string event_commands(const TranslatedEvent& ev, std::size_t k, bool no_z_motion) {
  const std::string n = std::to_string(k);
  if (ev.type == "insert") {
    // A released drop: created at its point with its release velocity (LAMMPS numbers it after the largest tag, which is the
    // drop's own tag while nothing is deleted: translation.cpp refuses outflow with release), its
    // size and mass set, and added to the integrated group.
    const std::string tag = std::to_string(ev.ball.tag);
    return "create_atoms " + std::to_string(ev.ball.type) + " single " + full_precision(ev.ball.x.x()) + " " +
           full_precision(ev.ball.x.y()) + " " + full_precision(ev.ball.x.z()) + " units box\n" + "set atom " + tag +
           " diameter " + full_precision(2.0 * ev.ball.radius) + " density " + full_precision(ev.ball.density) +
           " vx " + full_precision(ev.ball.v.x()) + " vy " + full_precision(ev.ball.v.y()) + " vz " +
           full_precision(ev.ball.v.z()) + "\ngroup mobile id " + tag + "\n";
  }
  if (ev.type == "move_wall") {
    // fix move linear sets the balls' velocity and places them at x_0 + V (t − t_0) before each
    // step's forces (motion/wall_motion.cpp: silodem's placement); a new velocity replaces the fix, and
    // a stopped wall keeps no velocity for the contact laws to read.
    if (ev.tags.empty()) return "";
    std::string id = ev.motion;
    for (char& ch : id)
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    std::string d = ev.moved_before ? "unfix " + id + "\n" : "group " + id + " id" + id_ranges(ev.tags) + "\n";
    if (ev.velocity.isZero()) return d + "velocity " + id + " set 0 0 0\n";
    return d + "fix " + id + " " + id + " move linear " + full_precision(ev.velocity.x()) + " " +
           full_precision(ev.velocity.y()) + " " + (no_z_motion ? "NULL" : full_precision(ev.velocity.z())) + "\n";
  }
  if (ev.type == "open_outlet") {
    if (ev.tags.empty()) return "";
    return "group gate" + n + " id" + id_ranges(ev.tags) + "\ndelete_atoms group gate" + n + " compress no\n";
  }
  // Sudden closure: the mobile balls whose centre lies in the slab are stopped and leave the
  // integrated group (gravity and nve/sphere act on "mobile" only), i.e. become wall balls.
  const double h = 0.5 * ev.thickness;
  return "region slab" + n + " cylinder z " + full_precision(ev.centre.x()) + " " + full_precision(ev.centre.y()) + " " +
         full_precision(0.5 * ev.diameter) + " " + full_precision(ev.centre.z() - h) + " " +
         full_precision(ev.centre.z() + h) + " units box\n" + "group closing" + n + " region slab" + n + "\n" +
         "group closing" + n + " intersect closing" + n + " mobile\n" + "velocity closing" + n + " set 0 0 0\n" +
         "group mobile subtract mobile closing" + n + "\n";
}

}  // namespace

/// Walls moving by a law (motion/motion_law.hpp): each wall's balls as a group moved by fix move,
/// which places them and sets their velocity (and a turn's spin) before each step's forces, as
/// silodem does: a harmonic translation by `move variable` with silodem's own closed form in the
/// code's elapsed `time`, so that phase and start time carry over (translation.cpp refuses turns).
std::string law_commands(const Translation& tr) {
  std::string d;
  const auto num = full_precision;
  for (const auto& m : tr.motions) {
    if (m.tags.empty()) continue;
    const silodem::MotionLaw& law = m.law;
    const std::string g = m.group;
    d += "group " + g + " id" + id_ranges(m.tags) + "\n";
    if (law.amplitude != 0.0) {
      const double w = 2.0 * silodem::kPi * law.frequency;
      const auto par = [&](double x) { return "(" + num(x) + ")"; };
      const std::string on = "(time>=" + par(law.start_time) + ")",
                        arg = par(w) + "*(time-" + par(law.start_time) + ")+" + par(law.phase);
      d += "variable " + g + "_a equal \"" + on + "*" + par(law.amplitude) + "*(sin(" + arg + ")-" + par(std::sin(law.phase)) + ")\"\n";
      d += "variable " + g + "_v equal \"" + on + "*" + par(law.amplitude * w) + "*cos(" + arg + ")\"\n";
      const char* axis[3] = {"x", "y", "z"};
      std::string fix = "fix " + g + " " + g + " move variable";
      for (const char* kind : {"a", "v"})
        for (int k = 0; k < 3; ++k) {
          // A 2-D run refuses any z motion, even a zero one: the out-of-plane axis stays NULL.
          if (k == 2 && tr.turned()) {
            fix += " NULL";
            continue;
          }
          d += "variable " + g + "_" + kind + axis[k] + " equal \"v_" + g + "_" + kind + "*" + par(law.direction[k]) + "\"\n";
          fix += " v_" + g + "_" + kind + axis[k];
        }
      d += fix + "\n";
    }
    if (law.angular_speed != 0.0) {
      // fix move rotate: positions turned from x0 by Ω (t − t0) about the axis, velocity ω × (x − c)
      // and the balls' spin ω, set before each step's forces (its period is 2π/|Ω|, the sense by
      // the axis).
      const silodem::Vec3 n = law.angular_speed > 0.0 ? law.axis : silodem::Vec3(-law.axis);
      d += "fix " + g + " " + g + " move rotate " + num(law.centre.x()) + " " + num(law.centre.y()) + " " +
           num(law.centre.z()) + " " + num(n.x()) + " " + num(n.y()) + " " + num(n.z()) + " " +
           num(2.0 * silodem::kPi / std::abs(law.angular_speed)) + "\n";
    }
  }
  return d;
}

std::string fix_move_limits(const Translation& tr) {
  for (const auto& m : tr.motions) {
    if (m.law.angular_speed == 0.0) continue;
    const std::string wall = "\"" + m.wall + "\"";
    if (m.law.amplitude != 0.0)
      return "wall " + wall + " turns and oscillates at once: fix move takes one style per group (rotate or variable)";
    if (m.law.start_time != 0.0)
      return "wall " + wall + " starts turning after t = 0: fix move rotate turns from the step it is defined";
  }
  return "";
}

namespace {

/// The bounds of a `block` region holding what lies below silodem's height z, in the code's axes
/// (silodem's z is a code axis up to its sign: the identity, or planar_turn's +y).
std::string below_region(const Translation& tr, double z) {
  const silodem::Vec3 up = tr.frame * silodem::Vec3::UnitZ();
  std::string bounds;
  for (int k = 0; k < 3; ++k)
    bounds += up[k] > 0.5 ? " INF " + full_precision(z) : up[k] < -0.5 ? " " + full_precision(-z) + " INF" : " INF INF";
  return bounds.substr(1);
}

}  // namespace

std::string lammps_family_motion(const silodem::CaseConfig& cfg, const Translation& tr, const std::string& dump_modify,
                                 OutflowStyle outflow, const std::string& integrate) {
  std::string d;
  const double g = cfg.gravity.norm();
  if (g > 0.0) {
    const silodem::Vec3 u = tr.frame * cfg.gravity / g;
    d += "fix grav mobile gravity " + full_precision(g) + " vector " + full_precision(u.x()) + " " +
         full_precision(u.y()) + " " + full_precision(u.z()) + "\n";
  }
  d += "fix integrate mobile " + integrate + "\n";
  d += law_commands(tr);
  // Last of the fixes that set forces: it zeroes the out-of-plane force and in-plane torques.
  if (tr.turned()) d += "fix planar all enforce2d\n";
  // Which balls are walls changes at a closure: every frame says so (column v_fixed).
  d += "variable fixed atom \"gmask(mobile)==0\"\n";
  // Angular velocity only where balls rotate: a frictionless dump keeps its size.
  d += "dump d all custom " + std::to_string(dump_interval(cfg)) + " dump.txt id mass radius x y z vx vy vz fx fy fz v_fixed" +
       (cfg.contact.rotation() ? " omegax omegay omegaz" : "") + "\n";
  d += dump_modify + "\n";
  d += "thermo " + std::to_string(std::max(1L, (tr.steps - tr.start_step) / 10)) + "\n";
  std::string run_suffix;
  if (tr.outflow_below_z) {
    d += "region outflow block " + below_region(tr, *tr.outflow_below_z) + " units box\n";
    if (outflow == OutflowStyle::Evaporate)
      d += "fix outflow mobile evaporate " + std::to_string(tr.outflow_every_steps) + " 1000000000 outflow 1\n";
    else run_suffix = " every " + std::to_string(tr.outflow_every_steps) + " \"delete_atoms region outflow compress no\"";
  }
  long at = tr.start_step;
  bool ran = false;
  for (std::size_t k = 0; k < tr.events.size(); ++k) {
    const TranslatedEvent& ev = tr.events[k];
    if (ev.step > at || !ran) d += "run " + std::to_string(ev.step - at) + (ev.step > at ? run_suffix : "") + "\n";
    ran = true;
    at = ev.step;
    d += event_commands(ev, k, tr.turned());
  }
  d += "run " + std::to_string(tr.steps - at) + (tr.steps > at ? run_suffix : "") + "\n";
  return d;
}

ReferenceBackend::Input lammps_family_input(const std::string& exe, const std::string& deck_file,
                                            const std::string& deck, const Translation& tr) {
  ReferenceBackend::Input in;
  in.files = {{deck_file, deck}, {"data.lmp", lammps_data_file(tr)}};
  in.main_file = deck;
  in.argv = {exe, "-in", deck_file, "-log", "none", "-echo", "none"};
  in.env = {"OMP_NUM_THREADS=1"};
  return in;
}

std::string lammps_data_file(const Translation& tr) {
  silodem::Vec3 lo = tr.balls.front().x, hi = lo;
  double r_max = 0.0;
  for (const auto& b : tr.balls) lo = lo.cwiseMin(b.x), hi = hi.cwiseMax(b.x), r_max = std::max(r_max, b.radius);
  // Released drops are created later: the box (shrink-wrapped with this minimum) must hold them.
  for (const auto& ev : tr.events)
    if (ev.type == "insert") lo = lo.cwiseMin(ev.ball.x), hi = hi.cwiseMax(ev.ball.x), r_max = std::max(r_max, ev.ball.radius);
  for (const auto& x : tr.box_holds) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double pad = 4.0 * r_max;
  std::string s = "silodem translation\n\n" + std::to_string(tr.balls.size()) + " atoms\n" +
                  std::to_string(tr.types.size()) + " atom types\n\n";
  char line[512];
  const char* names[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d) {
    std::snprintf(line, sizeof line, "%.17g %.17g %slo %shi\n", lo[d] - pad, hi[d] + pad, names[d], names[d]);
    s += line;
  }
  s += "\nAtoms # sphere\n\n";
  for (const auto& b : tr.balls) {
    std::snprintf(line, sizeof line, "%lld %d %.17g %.17g %.17g %.17g %.17g\n", static_cast<long long>(b.tag), b.type,
                  2.0 * b.radius, b.fixed ? b.density * tr.wall_density_factor : b.density, b.x.x(), b.x.y(), b.x.z());
    s += line;
  }
  s += "\nVelocities\n\n";
  for (const auto& b : tr.balls) {
    std::snprintf(line, sizeof line, "%lld %.17g %.17g %.17g %.17g %.17g %.17g\n", static_cast<long long>(b.tag), b.v.x(),
                  b.v.y(), b.v.z(), b.w.x(), b.w.y(), b.w.z());
    s += line;
  }
  return s;
}

}  // namespace harness
