#include "silodem/run/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <unistd.h>

#include "silodem/breakage/breakage_stage.hpp"
#include "silodem/case/memory_estimate.hpp"
#include "silodem/checkpoint/archive.hpp"
#include "silodem/checkpoint/checkpoint_file.hpp"
#include "silodem/contact/stiffest_pair.hpp"
#include "silodem/core/interrupt.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/core/progress.hpp"
#include "silodem/energy/energy_ledger.hpp"
#include "silodem/fill/drop_feeder.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/forces/surface_contacts.hpp"
#include "silodem/integrate/integrator.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/neighbour/spatial_order.hpp"
#include "silodem/output/checked_file.hpp"
#include "silodem/output/dump_writer.hpp"
#include "silodem/output/result_dir.hpp"
#include "silodem/output/series_writer.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/output/vtk_writer.hpp"
#include "silodem/probes/probe.hpp"
#include "silodem/run/guards.hpp"
#include "silodem/run/run_state.hpp"
#include "silodem/run/stages.hpp"
#include "silodem/motion/wall_motion.hpp"
#include "silodem/scene/scene_builder.hpp"
#include "silodem/stop/equilibrium.hpp"

namespace silodem {

namespace fs = std::filesystem;
using nlohmann::json;

std::string silodem_version() { return "0.1.0"; }

namespace {

/// The run's progress: where it is, how fast it goes (since this process started stepping), and
/// the time left at that pace.
std::string progress_text(const CaseConfig& cfg, double t, long steps, double simulated, std::size_t balls,
                          std::size_t mobile, double seconds, double drift) {
  // Ball-steps count the integrated (mobile) balls, as the benchmarks do.
  const double per_second = seconds > 0.0 ? 1.0 / seconds : 0.0;
  const double sim_rate = simulated * per_second;
  char b[320];
  std::snprintf(b, sizeof b,
                "t = %.4g / %.4g s (%.1f %%) | %.3g steps/s, %.3g ball-steps/s, %.3g simulated s per s | %s left | "
                "%zu mobile, energy drift %.2e",
                t, cfg.duration, 100.0 * t / cfg.duration, double(steps) * per_second,
                double(steps) * double(balls) * per_second, sim_rate,
                format_duration(sim_rate > 0.0 ? (cfg.duration - t) / sim_rate : INFINITY).c_str(), mobile, drift);
  return b;
}

/// Empty (and left out of the summary) if no pair can form. An overdamped unclamped pair never
/// ends its contact: its contact time is left out rather than written as infinity (JSON null).
json stiffest_json(const CaseConfig& cfg) {
  const auto sp = stiffest_pair(cfg);
  if (!sp) return json::object();
  json j = {{"pair", sp->description},  {"k", sp->k},
            {"c", sp->c},               {"m_eff", sp->m_eff},
            {"omega0", sp->behaviour.omega0}, {"damping_ratio", sp->behaviour.zeta},
            {"restitution", sp->behaviour.restitution}, {"omega0_dt", cfg.dt * sp->behaviour.omega0}};
  if (std::isfinite(sp->behaviour.duration)) {
    j["contact_time"] = sp->behaviour.duration;
    j["dt_over_contact_time"] = cfg.dt / sp->behaviour.duration;
  }
  return j;
}

/// What a checkpoint must match: the case as given and what the harness may set beside it.
std::uint64_t run_fingerprint(const CaseConfig& cfg) {
  char extra[160];
  std::snprintf(extra, sizeof extra, "|%a|%a|%ld|%llu|%zu", cfg.dt, cfg.duration, cfg.start_step,
                (unsigned long long)cfg.seed, cfg.balls.size());
  return case_fingerprint(cfg.name + "|" + cfg.source.dump() + extra);
}

/// Renumbers the mobile balls in slabs along the longest axis (neighbour/spatial_order.hpp), cubes of the
/// smallest mobile diameter, so a cube holds at most about one ball. Nothing happens if already in order
/// (nothing changes then: no bumped topology, no forced neighbour rebuild).
void renumber_mobile(Particles& p, Integrator& integrator) {
  if (p.n_mobile < 2) return;
  const double r_min = *std::min_element(p.r.begin(), p.r.begin() + std::ptrdiff_t(p.n_mobile));
  const std::vector<std::uint32_t> order = sweep_order(p, 2.0 * r_min);
  if (std::is_sorted(order.begin(), order.end())) return;  // a sorted permutation is the identity
  p.permute_mobile(order);
  integrator.permute_mobile(order);
}

/// Refuses, before anything runs, an output that would replace what silodem did not write.
void check_outputs(const fs::path& out, const std::vector<fs::path>& inputs) {
  check_output_dir(out, inputs, "--out");
  check_output_dir(out.string() + ".failed", inputs, "--out (its .failed sibling)");
  check_output_dir(out.string() + ".checkpoint", inputs, "--out (its .checkpoint sibling)");
}

void say(const CaseConfig& cfg, const std::vector<std::string>& lines) {
  for (const auto& l : lines) std::fprintf(stderr, "[%s] %s\n", cfg.name.c_str(), l.c_str());
}

}  // namespace

fs::path normal_out(const fs::path& dir) {
  fs::path out = dir.lexically_normal();
  if (!out.has_filename()) out = out.parent_path();
  return out;
}

json complete_summary_head(const CaseConfig& cfg) {
  return {{"format", "silodem-result/1"}, {"status", "complete"}, {"code", "silodem"}, {"code_version", silodem_version()},
          {"case", cfg.name},           {"seed", cfg.seed},        {"input", cfg.source}};
}

double default_skin(const CaseConfig& cfg) {
  double r_min = INFINITY;
  for (const auto& b : cfg.balls) r_min = std::min(r_min, b.radius);
  if (cfg.drops) r_min = std::min(r_min, cfg.drops->r_min);
  return 0.2 * r_min;
}

/// The run itself, writing into `tmp` (set once it is chosen) and publishing `out` at the end.
static json run_into(const CaseConfig& cfg, const RunOptions& opt, const fs::path& out, fs::path& tmp) {
  const auto wall_start = std::chrono::steady_clock::now();
  Scene scene = build_scene(cfg);
  Particles& p = scene.particles;
  const double g_abs = cfg.gravity.norm();
  WallMotion motion(cfg, p);

  const json stiff = stiffest_json(cfg);
  if (opt.banner) {
    std::fprintf(stderr, "[%s] dt = %.4g s, duration = %.4g s, %zu balls (%zu mobile)%s\n", cfg.name.c_str(), cfg.dt,
                 cfg.duration, p.size(), p.n_mobile, cfg.drops ? " + drops" : "");
    std::fprintf(stderr, "[%s] memory estimate %s\n", cfg.name.c_str(), estimate_run_memory(cfg).describe().c_str());
    if (!stiff.empty())
      std::fprintf(stderr, "[%s] stiffest pair %s: k = %.6g N/m, c = %.6g N s/m, t_c = %.6g s, e = %.6f, dt/t_c = %.4g\n",
                   cfg.name.c_str(), stiff["pair"].get<std::string>().c_str(), stiff["k"].get<double>(),
                   stiff["c"].get<double>(), stiff.value("contact_time", INFINITY), stiff["restitution"].get<double>(),
                   stiff.value("dt_over_contact_time", 0.0));
  }

  std::optional<DropFeeder> feeder;
  double drop_mass_max = 0.0, drop_k = 0.0;
  if (cfg.drops) {
    const Material& m = cfg.materials.at(cfg.drops->material);
    feeder.emplace(*cfg.drops, m, scene.material_index(m.name), cfg.gravity, cfg.seed, drop_tag(cfg, 0));
    drop_mass_max = sphere_mass(m.density, cfg.drops->r_max);
    drop_k = m.k;
  }
  const double skin = cfg.skin > 0.0 ? cfg.skin : default_skin(cfg);
  NeighbourList list(skin, max_cohesion_reach(p, cfg.contact, g_abs, drop_mass_max, drop_k));
  const auto field = make_force_field(cfg);
  const auto surfaces = make_surface_contacts(cfg, scene.material_names);  // null without smooth walls
  const bool spinning = surfaces && surfaces->spinning();
  // Where the loop's time goes, as LAMMPS's timing breakdown splits it ("Neigh", "Pair"): the list's
  // check and builds, and the force loop; the rest is integration, ledger, guards, probes and output.
  // Four clock reads per force evaluation; zeroed when the loop starts.
  double neighbour_seconds = 0.0, force_seconds = 0.0;
  const ForceEvaluation eval = [&](Particles& q) {
    const auto t0 = std::chrono::steady_clock::now();
    list.update(q);
    const auto t1 = std::chrono::steady_clock::now();
    ForceTotals totals = field->compute(q, list);
    if (surfaces) add_totals(totals, surfaces->compute(q));
    if (q.planar) q.keep_in_plane();
    neighbour_seconds += std::chrono::duration<double>(t1 - t0).count();
    force_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    return totals;
  };
  auto integrator = make_integrator(cfg.integrator, cfg.gravity);
  auto probes = make_probes(cfg, surfaces.get());

  // Results go to a temporary sibling first; renamed into place only when complete.
  tmp = fs::absolute(out).string() + ".partial-" + std::to_string(::getpid());
  const CheckpointStore checkpoints(out.string() + ".checkpoint", cfg.checkpoint.keep);
  const std::uint64_t fingerprint = run_fingerprint(cfg);

  EnergyLedger ledger(cfg.gravity, p.rotating);
  std::optional<SeriesWriter> series;
  long step = cfg.start_step;  // 0, or where a continuation (output/state_file.hpp) picks up
  double t = double(step) * cfg.dt;
  // A drop due at step 0 belongs to the initial state (as it does for a reference code, which
  // receives it as a ball); later drops bring their energy into the ledger as they come.
  const auto try_drop = [&](bool initial) {
    if (!feeder) return false;
    const auto rec = feeder->maybe_drop(p, step, t);
    if (!rec) return false;
    for (auto& pr : probes) pr->on_drop(*rec);
    if (rec->outcome != "placed") return false;
    if (!initial) {
      const std::string id = rec->recycled_id.empty() ? "drop" + std::to_string(rec->index) : rec->recycled_id;
      const std::size_t i = std::size_t(p.find(id));
      ledger.inject(p.m[i], p.x[i], p.v[i]);
    }
    return true;
  };
  StageController stages(cfg, ledger);
  std::optional<BreakageStage> breakage;
  if (cfg.breakage) breakage.emplace(*cfg.breakage, cfg.seed, scene.material_names);
  ForceTotals totals;
  double next_row = cfg.series_interval;
  std::optional<DumpWriter> dump;
  std::optional<VtkWriter> vtk;
  std::string stop_reason = "duration";
  long corrector_passes_total = 0, evaluations = 0;
  int corrector_passes_max = 0;
  double corrector_residual_max = 0.0;
  EquilibriumMeasure eq;
  ProgressLine progress(cfg.name, opt.progress ? progress_style(opt.progress_every) : ProgressStyle{});
  const long max_steps = long(std::ceil(cfg.duration / cfg.dt - 1e-9));
  RunGuards guards(cfg, p);
  double wall_before = 0.0;  // seconds the run used before the checkpoint it restarted from

  // Everything a step carries to the next, in one order for saving and for restoring.
  const auto state_io = [&](Archive& a, RunFiles& files) {
    RunParts parts{files,  step,     next_row, corrector_passes_total, evaluations, corrector_passes_max,
                   corrector_residual_max, totals, p, list, *field, surfaces.get(), *integrator, ledger, stages, guards,
                   feeder ? &*feeder : nullptr, breakage ? &*breakage : nullptr, probes};
    serialize_run(a, parts);
  };
  auto last_checkpoint = std::chrono::steady_clock::now();
  const auto save_checkpoint = [&] {
    RunFiles files{tmp.string(), series->flushed_bytes(), dump ? dump->flushed_bytes() : 0, dump.has_value(),
                   wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count()};
    Archive a = Archive::writer();
    state_io(a, files);
    try {
      checkpoints.save(fingerprint, step, a.bytes());
    } catch (const CheckpointError& e) {
      throw WriteError(checkpoints.dir(), e.what());
    }
    last_checkpoint = std::chrono::steady_clock::now();
  };
  const auto checkpoint_due = [&] {
    if (cfg.checkpoint.interval_steps > 0 && step % cfg.checkpoint.interval_steps == 0) return true;
    return cfg.checkpoint.interval_seconds > 0.0 && (step & 63) == 0 &&
           std::chrono::steady_clock::now() - last_checkpoint > std::chrono::duration<double>(cfg.checkpoint.interval_seconds);
  };

  // A stop signal ends the run between steps: the state saved if the case checkpoints, the partial
  // directory marked interrupted (never renamed to DIR), exit 128 + signal (core/interrupt.hpp).
  const auto stop_on_signal = [&](int sig) {
    const bool resumable = cfg.checkpoint.enabled();
    if (resumable) save_checkpoint();
    static_cast<void>(series->flushed_bytes());
    if (dump) static_cast<void>(dump->flushed_bytes());
    const std::string name = signal_name(sig);
    write_file_checked(tmp / "summary.json",
                       json{{"case", cfg.name}, {"status", "interrupted"}, {"signal", name}, {"step", step}, {"time", t},
                            {"resumable", resumable}}.dump(2) + "\n");
    write_marker(tmp, "run", "interrupted");
    char at[96];
    std::snprintf(at, sizeof at, " at step %ld, t = %.6g s", step, t);
    throw Interrupted(sig, "[" + cfg.name + "] interrupted by " + name + at + "; partial results in " + tmp.string() +
                               " (not a result)" +
                               (resumable ? "; the state is checkpointed in " + checkpoints.dir().string() +
                                                ": resume with --restart"
                                          : "; the case has no \"checkpoint\" section, so the run cannot be resumed"));
  };

  if (opt.restart) {
    auto loaded = checkpoints.newest_valid(fingerprint);
    for (const auto& r : loaded.refused) std::fprintf(stderr, "[%s] checkpoint refused: %s\n", cfg.name.c_str(), r.c_str());
    Archive a = Archive::reader(std::move(loaded.payload));
    RunFiles files;
    state_io(a, files);
    a.expect_end();
    for (const auto m : p.material)
      if (m < 0 || std::size_t(m) >= scene.material_names.size())
        throw CheckpointError(loaded.file.string() + ": a ball's material index is not one of the case's materials");
    if (step != loaded.step || step < cfg.start_step || step > max_steps)
      throw CheckpointError(loaded.file.string() + ": its step does not fit the case");
    if (files.has_dump != (cfg.dump_interval_steps > 0))
      throw CheckpointError(loaded.file.string() + ": written with another dump setting");
    // The checkpoint names the directory it appends to; only a sibling temporary of DIR is taken
    // (a damaged or crafted file must not make a restart cut back some other file).
    const fs::path partial = fs::path(files.partial).lexically_normal();
    if (partial.parent_path() != fs::absolute(out).parent_path() ||
        partial.filename().string().rfind(out.filename().string() + ".partial-", 0) != 0)
      throw CheckpointError(loaded.file.string() + ": names " + files.partial + ", not a temporary directory of " + out.string());
    tmp = partial;
    if (!read_marker(tmp)) throw CheckpointError(loaded.file.string() + ": names " + tmp.string() + ", which silodem did not mark as its own");
    say(cfg, clean_stale_partials(out, tmp));
    t = double(step) * cfg.dt;
    series.emplace(tmp / "series.csv", files.series_bytes);
    if (files.has_dump) dump.emplace(tmp / "dump.txt", files.dump_bytes);
    if (cfg.vtk_interval_steps > 0) vtk.emplace(tmp / "vtk", cfg.dt, cfg.vtk_float64);
    wall_before = files.wall_seconds;
    if (opt.banner)
      std::fprintf(stderr, "[%s] restarting from %s: step %ld, t = %.6g s\n", cfg.name.c_str(), loaded.file.c_str(), step, t);
  } else {
    // A fresh run: checkpoints of an earlier run of this directory are no longer its past.
    say(cfg, clean_stale_partials(out));
    remove_marked(checkpoints.dir());
    remove_marked(tmp);
    std::error_code ec;
    fs::create_directories(tmp / "probes", ec);
    if (ec) throw WriteError(tmp / "probes", "cannot create the directory: " + ec.message());
    write_marker(tmp, "run", "partial");
    series.emplace(tmp / "series.csv");
    motion.place(p, t);
    try_drop(true);
    totals = integrator->reset(p, eval);
    ledger.start(p, totals, t);
    for (auto& pr : probes) pr->sample(p, t);
    series->row(ledger.state(), p, totals);
    if (cfg.dump_interval_steps > 0) {
      dump.emplace(tmp / "dump.txt");
      dump->frame(0, p);
    }
    if (cfg.vtk_interval_steps > 0) {
      vtk.emplace(tmp / "vtk", cfg.dt, cfg.vtk_float64);
      vtk->frame(step, p);
    }
  }
  // A guard that trips leaves the last state and a failed summary in DIR.failed for inspection
  // (never in DIR: nothing that looks complete), then the error goes on to the caller (exit 3).
  // The step loop's own time, comparable with LAMMPS's and LIGGGHTS's "Loop time" (no set-up, no
  // reading of the case, no result files).
  const auto loop_start = std::chrono::steady_clock::now();
  const long loop_first_step = step;
  const double loop_first_time = t;
  neighbour_seconds = force_seconds = 0.0;
  try {
  while (step < max_steps) {
    // Between steps, where ü is the only per-ball state carried over. By the global step count,
    // so a restart or a continuation renumbers at the same steps as the run it continues.
    if (cfg.sort_interval_steps > 0 && step % cfg.sort_interval_steps == 0) renumber_mobile(p, *integrator);
    bool changed = stages.apply(p, step, t, feeder ? &*feeder : nullptr);
    for (const auto& e : stages.take_exits())
      for (auto& pr : probes) pr->on_exit(e);
    changed = (step > cfg.start_step && try_drop(false)) || changed;
    // Grains due to break (after the last step's contact ends) become their fragments here.
    std::vector<std::int64_t> born;
    if (breakage) {
      born = breakage->break_due(p, t);
      field->set_newborn(born);
    }
    if (changed || !born.empty()) {
      totals = integrator->reset(p, eval);
      ++evaluations;
    }
    if (!born.empty()) breakage->add_work(ledger.book_breakage(p, totals));
    // A moving wall goes to its place at the step's end before the step: this step's starting
    // forces are evaluated already, and its own evaluation is the first to read wall positions.
    // Its work on the grains enters the ledger by the trapezoidal rule.
    const double wall_power_start = p.moving_walls ? motion.advance(p, double(step + 1) * cfg.dt, cfg.dt) : 0.0;
    const double surface_power_start = spinning ? surfaces->power() : 0.0;
    const StepReport rep = integrator->step(p, eval, cfg.dt);
    if (p.moving_walls) ledger.add_wall_work(0.5 * (wall_power_start + wall_power(p)) * cfg.dt);
    if (spinning) ledger.add_wall_work(0.5 * (surface_power_start + surfaces->power()) * cfg.dt);
    if (rep.viscous_dissipated != 0.0) ledger.add_viscous_work(rep.viscous_dissipated);
    field->commit();  // the step is accepted: contact history moves on (forces/contact_history.hpp)
    if (breakage) {
      const std::vector<ContactEnd> ended = field->take_ended_contacts();
      if (breakage->counts_at(t)) breakage->absorb(ended, p);
    }
    if (surfaces) surfaces->commit();
    ++step;
    t = double(step) * cfg.dt;
    totals = rep.totals;
    evaluations += rep.force_evaluations;
    corrector_passes_total += rep.corrector_passes;
    corrector_passes_max = std::max(corrector_passes_max, rep.corrector_passes);
    corrector_residual_max = std::max(corrector_residual_max, rep.corrector_residual);
    ledger.record(p, totals, t, cfg.dt);
    guards.check(p, list, totals, ledger.state(), step, t);
    for (auto& pr : probes) pr->sample(p, t);
    if (dump && step % cfg.dump_interval_steps == 0) dump->frame(step, p);
    if (vtk && step % cfg.vtk_interval_steps == 0) vtk->frame(step, p);
    if (t >= next_row - 0.5 * cfg.dt) {
      series->row(ledger.state(), p, totals);
      next_row += cfg.series_interval;
    }
    if (cfg.equilibrium.enabled && step % cfg.equilibrium.check_interval_steps == 0 &&
        t >= cfg.equilibrium.min_time && (!feeder || feeder->done())) {
      eq = measure_equilibrium(p, integrator->acceleration(), g_abs, cfg.equilibrium, ledger.state().kinetic,
                               ledger.state().elastic);
      if (eq.at_rest()) {
        stop_reason = "equilibrium";
        break;
      }
    }
    if (cfg.checkpoint.enabled() && checkpoint_due()) save_checkpoint();
    if (const int sig = stop_signal()) stop_on_signal(sig);
    if ((step & 63) == 0 && progress.due())
      progress.print(progress_text(cfg, t, step - loop_first_step, t - loop_first_time, p.n_mobile, p.n_mobile,
                                   std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count(),
                                   ledger.state().relative_drift()));
  }
  } catch (const RunError& e) {
    // Only a finite state is written: a blown-up one would put NaN (nlohmann: null) in state.json.
    const bool finite = state_is_finite(p);
    if (finite) write_states(tmp, cfg, p, scene.material_names, step, t);
    series->close();
    if (dump) dump->close();
    json failed_summary = {{"case", cfg.name}, {"status", "failed"}, {"error", e.what()}, {"step", step}, {"time", t},
                           {"files", {{"series", "series.csv"}}}};
    if (finite) failed_summary["files"]["state"] = state_file_name(cfg), failed_summary["files"]["state_compact"] = "state.sds";
    else failed_summary["state_omitted"] = "the state at this step is not finite; series.csv ends at the last step the guards passed";
    write_file_checked(tmp / "summary.json", failed_summary.dump(2) + "\n");
    const fs::path failed = out.string() + ".failed";
    publish(tmp, failed, "failed");
    std::string older;
    if (const auto m = read_marker(out); m && m->state == "complete")
      older = "; " + out.string() + " still holds an earlier complete result (written " + m->written + "), not this run's";
    throw RunError(std::string(e.what()) + (finite ? " [last state: " + (failed / state_file_name(cfg)).string()
                                                   : " [no state written, it is not finite; the series up to the last "
                                                     "step the guards passed: " + (failed / "series.csv").string()) +
                   older + "]");
  }
  progress.finish();
  const double loop_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();
  if (cfg.series_interval > 0.0 && std::abs(ledger.state().t - (next_row - cfg.series_interval)) > 0.5 * cfg.dt)
    series->row(ledger.state(), p, totals);
  if (vtk) {
    if (step % cfg.vtk_interval_steps != 0) vtk->frame(step, p);  // the final state is always a frame
    vtk->finish();
  }
  series->close();  // checked, before the directory is published
  if (dump) dump->close();
  if (cfg.equilibrium.enabled && stop_reason != "equilibrium")
    eq = measure_equilibrium(p, integrator->acceleration(), g_abs, cfg.equilibrium, ledger.state().kinetic,
                               ledger.state().elastic);

  write_states(tmp, cfg, p, scene.material_names, step, t);
  json probe_digest = json::object();
  for (const auto& pr : probes) probe_digest[pr->name()] = pr->write(tmp / "probes");
  if (breakage) breakage->write(tmp);

  const double wall_seconds =
      wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  json materials = json::object();
  for (const auto& [name, m] : cfg.materials) {
    materials[name] = {{"density", m.density}, {"k", m.k}, {"c", m.c}, {"derived_from", m.derived_from}};
    if (cfg.contact.rotation())
      materials[name].update({{"friction", m.friction}, {"rolling_friction", m.rolling_friction},
                              {"shear_stiffness_ratio", m.shear_stiffness_ratio},
                              {"tangential_damping_ratio", m.tangential_damping_ratio}});
    if (cfg.contact.normal == NormalModel::Hertz)
      materials[name].update({{"youngs_modulus", m.youngs_modulus}, {"poisson_ratio", m.poisson_ratio},
                              {"hertz_damping_ratio", m.hertz_damping_ratio}});
  }
  Vec3 wf = wall_force_resultant(p);
  json surface_loads = json::object();  // the smooth walls' loads, also in the resultant
  if (surfaces)
    for (std::size_t k = 0; k < surfaces->surfaces().size(); ++k) {
      const Vec3& l = surfaces->loads()[k];
      surface_loads[surfaces->surfaces()[k].name] = {l.x(), l.y(), l.z()};
      wf += l;
    }
  double z_top = -INFINITY, mass = 0.0;
  for (std::size_t i = 0; i < p.n_mobile; ++i) z_top = std::max(z_top, p.x[i].z() + p.r[i]), mass += p.m[i];
  json summary = complete_summary_head(cfg);
  summary.update({
      {"derived", {{"materials", materials}, {"dt", cfg.dt}, {"skin", skin},
                   {"sort_interval_steps", cfg.sort_interval_steps}}},
      {"run",
       {{"steps", step - cfg.start_step},
        {"start_step", cfg.start_step},
        {"time", t},
        {"stop_reason", stop_reason},
        {"wall_seconds", wall_seconds},
        {"loop_seconds", loop_seconds},
        {"loop_breakdown_seconds",
         {{"neighbour", neighbour_seconds}, {"force", force_seconds}, {"other", loop_seconds - neighbour_seconds - force_seconds}}},
        {"threads", threads()},
        {"force_evaluations", evaluations},
        {"neighbour_builds", list.builds()},
        {"corrector_passes_mean", step > cfg.start_step ? double(corrector_passes_total) / double(step - cfg.start_step) : 0.0},
        {"corrector_passes_max", corrector_passes_max},
        {"corrector_residual_max", corrector_residual_max}}},
      {"balls", {{"mobile", p.n_mobile}, {"fixed", p.size() - p.n_mobile}}},
      // What the solver holds (heap capacities), at the end: ball arrays, neighbour list (with
      // its reverse index), the force loop's per-pair and per-ball scratch, the integrator's state.
      {"memory",
       {{"particles_bytes", p.bytes()},
        {"neighbour_list_bytes", list.bytes()},
        {"force_buffers_bytes", field->bytes() + (surfaces ? surfaces->bytes() : 0)},
        {"integrator_bytes", integrator->bytes()},
        {"list_pairs", list.pair_count()},
        {"estimated_bytes", estimate_run_memory(cfg).total()},  // case/memory_estimate.hpp, from the case alone
        {"total_bytes", p.bytes() + list.bytes() + field->bytes() + (surfaces ? surfaces->bytes() : 0) + integrator->bytes()}}},
      {"energy", ledger.summary()},
      {"wall_force", {wf.x(), wf.y(), wf.z()}},
      {"surface_loads", surface_loads},
      {"fill", {{"mobile_mass", mass}, {"z_top", p.n_mobile ? z_top : 0.0}}},
      {"probes", probe_digest},
      {"files", {{"series", "series.csv"}, {"probes", "probes/"}, {"dump", cfg.dump_interval_steps > 0 ? "dump.txt" : ""},
                 {"vtk", cfg.vtk_interval_steps > 0 ? "vtk/balls.pvd vtk/walls.pvd" : ""},
                 {"state", state_file_name(cfg)}, {"state_compact", "state.sds"}}}});
  if (!stiff.empty()) summary["derived"]["stiffest_pair"] = stiff;
  if (const auto tol = integrator->corrector_tolerance()) {
    // A step that ran out of passes has a residual at or above the tolerance: said, not hidden.
    const bool converged = corrector_residual_max < *tol;
    summary["run"]["corrector_converged"] = converged;
    summary["run"]["corrector_tolerance"] = *tol;
    if (!converged)
      std::fprintf(stderr,
                   "[%s] the corrector reached its pass limit (%d) unconverged: largest residual %.3g against %.3g "
                   "(a tolerance below what the passes reach, or w dt beyond sqrt(6) on the tangent stiffness: docs/theory.md §7.4)\n",
                   cfg.name.c_str(), corrector_passes_max, corrector_residual_max, *tol);
  }
  if (cfg.equilibrium.enabled) {
    summary["equilibrium"] = {{"test", eq.kinetic ? "forces_and_kinetic" : "paper_literal"},
                              {"f_max", eq.f_max}, {"eps_f", eq.eps_f}, {"f_total", eq.f_total},
                              {"eps_ft", eq.eps_ft}, {"e_kin", eq.e_kin}, {"e_el", eq.e_el}, {"at_rest", eq.at_rest()}};
    if (eq.kinetic) summary["equilibrium"]["eps_k"] = eq.eps_k;
  }
  if (feeder) {
    // No nulls: the fill height only when there is one (an inlet with a ball under it), the time
    // the fill was full only when it was.
    summary["drops"] = {{"placed", feeder->placed()}, {"rejected", feeder->rejected()},
                        {"recycled_waiting", feeder->waiting()}, {"full", feeder->full()}};
    const double surface = feeder->surface_height(p);
    if (std::isfinite(surface)) summary["drops"]["surface_height"] = surface;
    if (feeder->full()) summary["drops"]["full_time"] = feeder->full_time();
  }
  if (breakage) summary["breakage"] = breakage->summary();
  if (!cfg.events.empty() || cfg.outflow.enabled) summary["stages"] = {{"fixed_at_closure", stages.converted()}};
  write_file_checked(tmp / "summary.json", summary.dump(2) + "\n");
  publish(tmp, out, "complete");
  remove_marked(checkpoints.dir());
  // A failed run of this path is older than this result now: not left to be mistaken for it.
  if (read_marker(out.string() + ".failed")) remove_marked(out.string() + ".failed");
  return summary;
}

json run_case(const CaseConfig& cfg, const RunOptions& opt) {
  const fs::path out = normal_out(opt.out_dir);
  check_outputs(out, opt.inputs);
  fs::path tmp;  // the partial directory, once chosen
  try {
    return run_into(cfg, opt, out, tmp);
  } catch (const WriteError& e) {
    std::string fate;
    std::error_code ec;
    if (!tmp.empty() && fs::exists(tmp, ec)) {
      if (cfg.checkpoint.enabled() && read_marker(tmp)) {
        fate = "; the partial results stay in " + tmp.string() + ": with room again, --restart resumes them";
      } else {
        try {
          remove_marked(tmp);  // ours and incomplete; the one way silodem deletes a directory
          fate = "; no result directory was created";
        } catch (const JobStop&) {
          fate = "; " + tmp.string() + " is left (not marked as silodem's); no result directory was created";
        }
      }
    } else {
      fate = "; no result directory was created";
    }
    throw JobStop(e.exit_code(), std::string(e.what()) + fate);
  }
}

}  // namespace silodem
