#include "silodem/mpi/distributed_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <unistd.h>

#include "silodem/core/progress.hpp"
#include "silodem/core/run_error.hpp"
#include "silodem/energy/energy_ledger.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/integrate/integrator.hpp"
#include "silodem/mpi/domain.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/output/checked_file.hpp"
#include "silodem/output/result_dir.hpp"
#include "silodem/output/series_writer.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/run/guards.hpp"
#include "silodem/scene/scene_builder.hpp"

namespace silodem::mpi {

namespace fs = std::filesystem;
using nlohmann::json;

std::string unsupported_by_ranks(const CaseConfig& cfg) {
  if (cfg.integrator.scheme != Scheme::VelocityVerlet) return "an integrator other than velocity_verlet (\"integrator\")";
  if (cfg.drops) return "drops (\"drops\")";
  if (cfg.outflow.enabled || !cfg.events.empty()) return "stages (\"outflow\", \"events\")";
  if (cfg.breakage) return "breakage (\"breakage\")";
  if (!cfg.surfaces.empty()) return "smooth walls (\"surfaces\")";
  for (const WallSpec& w : cfg.walls)
    if (w.motion) return "walls in motion (\"walls\"[].motion)";
  if (!cfg.probes.empty()) return "probes (\"probes\")";
  if (cfg.equilibrium.enabled) return "the equilibrium stop test (\"equilibrium\")";
  if (cfg.checkpoint.enabled()) return "checkpoints (\"checkpoint\")";
  if (cfg.dump_interval_steps > 0 || cfg.vtk_interval_steps > 0) return "dumps and VTK frames (\"output\")";
  return {};
}

namespace {

/// The whole scene's final state, in global order, for the state files: the mobile balls gathered
/// from every process, then the wall balls every process holds.
Particles whole_scene(const std::vector<Domain::Record>& mobile, const Particles& local) {
  Particles whole = local.empty_like();
  whole.reserve(mobile.size() + local.size() - local.n_mobile);
  for (const Domain::Record& r : mobile) whole.add(r.ball, false);
  for (std::size_t i = local.n_mobile; i < local.size(); ++i) whole.add(local.ball(i), true);
  return whole;
}

/// Checks the output paths as one process does and makes DIR.partial-<pid>, marked as silodem's.
fs::path partial_dir(const CaseConfig& cfg, const RunOptions& opt, const fs::path& out) {
  check_output_dir(out, opt.inputs, "--out");
  check_output_dir(out.string() + ".failed", opt.inputs, "--out (its .failed sibling)");
  const fs::path tmp = fs::absolute(out).string() + ".partial-" + std::to_string(::getpid());
  for (const auto& line : clean_stale_partials(out)) std::fprintf(stderr, "[%s] %s\n", cfg.name.c_str(), line.c_str());
  remove_marked(tmp);
  std::error_code ec;
  fs::create_directories(tmp, ec);
  if (ec) throw WriteError(tmp, "cannot create the directory: " + ec.message());
  write_marker(tmp, "run", "partial");
  return tmp;
}

/// summary.json of a run on several processes: the one-process summary's fields that this run
/// has, with the process count and the redistributions.
json summary_json(const CaseConfig& cfg, const Particles& whole, const Particles& local, const EnergyLedger& ledger,
                  json run) {
  const Vec3 wf = wall_force_resultant(local);
  double mass = 0.0;
  for (std::size_t i = 0; i < whole.n_mobile; ++i) mass += whole.m[i];
  const double skin = cfg.skin > 0.0 ? cfg.skin : default_skin(cfg);
  json summary = complete_summary_head(cfg);
  summary.update({
          {"derived", {{"dt", cfg.dt}, {"skin", skin}, {"sort_interval_steps", cfg.sort_interval_steps}}},
          {"run", std::move(run)},
          {"balls", {{"mobile", whole.n_mobile}, {"fixed", whole.size() - whole.n_mobile}}},
          {"energy", ledger.summary()},
          {"wall_force", {wf.x(), wf.y(), wf.z()}},
          {"fill", {{"mobile_mass", mass}}},
          {"files", {{"series", "series.csv"}, {"state", state_file_name(cfg)}, {"state_compact", "state.sds"}}}});
  return summary;
}

}  // namespace

json run_distributed(const CaseConfig& cfg, const RunOptions& opt, MpiPartition& part) {
  if (const std::string why = unsupported_by_ranks(cfg); !why.empty())
    throw CaseError(cfg.name, "a run on several processes does not cover " + why +
                                  " yet (docs/cluster.md): run the case on one process, with threads");
  const auto wall_start = std::chrono::steady_clock::now();
  const bool root = part.rank() == 0;

  // Rank 0 writes the results, into a temporary sibling renamed into place when complete.
  const fs::path out = normal_out(opt.out_dir);
  const fs::path tmp = root ? partial_dir(cfg, opt, out) : fs::path();
  std::optional<SeriesWriter> series;
  if (root) series.emplace(tmp / "series.csv");

  Scene scene = build_scene(cfg);
  Particles& p = scene.particles;
  if (p.moving_walls) throw CaseError(cfg.name, "a run on several processes does not cover wall balls with a velocity yet");
  const double skin = cfg.skin > 0.0 ? cfg.skin : default_skin(cfg);
  NeighbourList list(skin, max_cohesion_reach(p, cfg.contact, cfg.gravity.norm(), 0.0, 0.0));
  const auto field = make_force_field(cfg);
  auto integrator = make_integrator(cfg.integrator, cfg.gravity);
  const RunGuards guards(cfg, p);  // its domain from the whole scene, as on one process
  double r_max = 0.0;
  for (const double r : p.r) r_max = std::max(r_max, r);
  // Ghosts within the farthest listed pair and a margin of one skin: redistributed when balls
  // have closed half of it, which at the usual speeds is every few list rebuilds.
  Domain domain(part, 2.0 * r_max + list.reach() + skin, skin);
  domain.distribute(p, *integrator);
  set_partition(&part);
  if (opt.banner && root)
    std::fprintf(stderr, "[%s] %d processes, %zu mobile balls (%zu on rank 0, %zu ghosts), dt = %.4g s, duration = %.4g s\n",
                 cfg.name.c_str(), part.ranks(), domain.global_mobile(), part.own_end - part.own_begin, domain.ghosts(),
                 cfg.dt, cfg.duration);

  const ForceEvaluation eval = [&](Particles& q) {
    domain.refresh_ghosts(q);
    list.update(q);
    ForceTotals totals = field->compute(q, list);
    if (q.planar) q.keep_in_plane();
    return totals;
  };
  EnergyLedger ledger(cfg.gravity, p.rotating);
  long step = cfg.start_step, evaluations = 1;
  double t = double(step) * cfg.dt, next_row = cfg.series_interval;
  const long max_steps = long(std::ceil(cfg.duration / cfg.dt - 1e-9));
  ForceTotals totals = integrator->reset(p, eval);
  ledger.start(p, totals, t);
  const auto row = [&] {
    field->finish_walls(p, list);  // the walls' loads, summed across processes, only when read
    if (root) series->row(ledger.state(), domain.global_mobile(), wall_force_resultant(p), totals);
  };
  row();
  ProgressLine progress(cfg.name, opt.progress && root ? progress_style(opt.progress_every) : ProgressStyle{});
  const auto loop_start = std::chrono::steady_clock::now();
  bool redistribute = false;
  while (step < max_steps) {
    // At the steps where one process renumbers (run/simulation.cpp): the same new order.
    const bool renumber = cfg.sort_interval_steps > 0 && step % cfg.sort_interval_steps == 0;
    if (renumber)
      domain.redistribute(p, *integrator, *field, true);
    else if (redistribute)
      domain.reselect_ghosts(p, *integrator);
    const StepReport rep = integrator->step(p, eval, cfg.dt);
    field->commit();
    ++step;
    t = double(step) * cfg.dt;
    totals = rep.totals;
    evaluations += rep.force_evaluations;
    ledger.record(p, totals, t, cfg.dt);
    guards.check(p, list, totals, ledger.state(), step, t);
    if (t >= next_row - 0.5 * cfg.dt) {
      row();
      next_row += cfg.series_interval;
    }
    redistribute = domain.redistribution_due(p);  // before the next step, with a renumbering if one is due
    if (root && (step & 63) == 0 && progress.due()) {
      char b[200];
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();
      std::snprintf(b, sizeof b, "t = %.4g / %.4g s | %d processes | %.3g steps/s | %zu redistributions", t, cfg.duration,
                    part.ranks(), s > 0.0 ? double(step - cfg.start_step) / s : 0.0, domain.redistributions());
      progress.print(b);
    }
  }
  progress.finish();
  const double loop_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();
  if (cfg.series_interval > 0.0 && std::abs(ledger.state().t - (next_row - cfg.series_interval)) > 0.5 * cfg.dt) row();
  field->finish_walls(p, list);
  const std::vector<Domain::Record> mobile = domain.gather_owned(p, nullptr);
  set_partition(nullptr);
  if (!root) return json::object();

  series->close();
  const Particles whole = whole_scene(mobile, p);
  write_states(tmp, cfg, whole, scene.material_names, step, t);
  const json summary = summary_json(
      cfg, whole, p, ledger,
      {{"steps", step - cfg.start_step},
       {"start_step", cfg.start_step},
       {"time", t},
       {"stop_reason", "duration"},
       {"wall_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count()},
       {"loop_seconds", loop_seconds},
       {"threads", 1},
       {"ranks", part.ranks()},
       {"redistributions", domain.redistributions()},
       {"force_evaluations", evaluations},
       {"neighbour_builds_rank0", list.builds()}});
  write_file_checked(tmp / "summary.json", summary.dump(2) + "\n");
  publish(tmp, out, "complete");
  if (read_marker(out.string() + ".failed")) remove_marked(out.string() + ".failed");
  return summary;
}

}  // namespace silodem::mpi
