#include "harness/trace/reconstruct.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <stdexcept>

#include "harness/trace/dump_reader.hpp"
#include "silodem/energy/energy_ledger.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/output/checked_file.hpp"
#include "silodem/output/manifest.hpp"
#include "silodem/output/series_writer.hpp"
#include "silodem/probes/probe.hpp"
#include "silodem/motion/wall_motion.hpp"

namespace harness {

namespace fs = std::filesystem;
using nlohmann::json;

json reconstruct_result(const silodem::CaseConfig& cfg, const Translation& tr, const fs::path& dump,
                        const fs::path& out, const json& meta) {
  // The scene's material indices (scene_builder: the case's names in order), which the Hertz law's pair table reads.
  std::map<std::string, std::int32_t> material_index;
  for (const auto& [name, m] : cfg.materials) material_index.emplace(name, std::int32_t(material_index.size()));
  std::map<std::int64_t, const TranslatedBall*> by_tag;
  for (const auto& b : tr.balls) by_tag[b.tag] = &b;
  for (const auto& ev : tr.events)
    if (ev.type == "insert") by_tag[ev.ball.tag] = &ev.ball;  // released drops join the dump later
  std::error_code ec;
  fs::create_directories(out / "probes", ec);
  if (ec) throw silodem::WriteError(out / "probes", "cannot create the directory: " + ec.message());
  const double g_abs = cfg.gravity.norm();
  // The normal law is a function of the dumped state; tangential and rolling springs are not (their
  // history is not in the dump): the rebuild evaluates the normal law alone, and the ledger says
  // which terms it could not rebuild.
  silodem::CaseConfig normal_only = cfg;
  normal_only.contact.tangential = silodem::TangentialModel::None;
  normal_only.contact.rolling = silodem::RollingModel::None;
  const auto field = silodem::make_force_field(normal_only);
  const bool rotating = cfg.contact.rotation();
  auto probes = silodem::make_probes(cfg);
  for (auto& pr : probes)
    for (const auto& d : tr.drops) pr->on_drop(d);
  silodem::EnergyLedger ledger(cfg.gravity, rotating);
  silodem::SeriesWriter series(out / "series.csv");

  DumpReader reader(dump);
  DumpFrame frame;
  long frames = 0, prev_step = 0;
  double t = 0.0;
  silodem::Particles p;
  silodem::ForceTotals totals;
  std::map<std::int64_t, bool> seen;  // tags of earlier frames: a new tag is a ball that came in
  struct Last {
    const TranslatedBall* ball;
    silodem::Vec3 x, v;
  };
  std::map<std::int64_t, Last> mobile_before;  // the previous frame's mobile balls
  double power_before = 0.0;                    // the walls' power on the grains at the previous frame
  std::vector<std::int64_t> tags_before;        // the previous frame's tags in particle order
  std::uint64_t topology = 0;
  const silodem::Mat3 back = tr.frame.transpose();
  while (reader.next(frame)) {
    if (tr.turned())  // the code ran in its own axes (planar_frame.hpp): back to silodem's
      for (auto& a : frame.atoms) a.x = back * a.x, a.v = back * a.v, a.f = back * a.f, a.w = back * a.w;
    // In tag order, whatever the code's row order (silodem dumps in its particle order, which its
    // spatial sorting changes): the same arrays for every code, and few index refreshes below.
    std::sort(frame.atoms.begin(), frame.atoms.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    p = silodem::Particles{};
    if (rotating) p.enable_rotation();
    std::map<std::int64_t, bool> fixed_now;
    for (const auto& a : frame.atoms) {
      const auto it = by_tag.find(a.id);
      if (it == by_tag.end()) throw std::runtime_error("dump has an atom with unknown id " + std::to_string(a.id));
      const TranslatedBall& b = *it->second;
      const ParticleType& ty = tr.types[std::size_t(b.type - 1)];
      // A closure turns mobile balls into wall balls mid-run: the dump's flag wins where there is one.
      const bool is_fixed = a.fixed >= 0 ? a.fixed == 1 : b.fixed;
      if (rotating && !a.has_w) throw std::runtime_error("the case rotates its balls but the dump has no omegax, omegay, omegaz");
      p.add({a.x, a.v, b.radius, b.mass, ty.k, ty.c, material_index.at(ty.material), b.id, b.tag, a.w}, is_fixed);
      fixed_now[a.id] = is_fixed;
    }
    // The probes keep a ball's index while p.topology stays: it changes exactly when the order does.
    if (p.tag != tags_before) ++topology, tags_before = p.tag;
    p.topology = topology;
    t = double(frame.step) * cfg.dt;
    // Stage changes since the last frame (run/stages.cpp books them the same way): a mobile ball
    // gone has left through the outlet, one now fixed was stopped by a closure. Both take their
    // energy out of the ledger, at the last state the dump shows (the frame interval bounds the error).
    for (const auto& [tag, last] : mobile_before) {
      const auto it = fixed_now.find(tag);
      if (it != fixed_now.end() && !it->second) continue;
      ledger.withdraw(last.ball->mass, last.x, last.v);
      if (it == fixed_now.end() && cfg.outflow.enabled)
        for (auto& pr : probes) pr->on_exit({t, last.ball->id, last.ball->mass, last.x});
    }
    mobile_before.clear();
    for (const auto& a : frame.atoms)
      if (!fixed_now[a.id]) mobile_before[a.id] = {by_tag[a.id], a.x, a.v};
    // The contact law evaluated on the dumped state gives the elastic energy and dashpot power.
    silodem::NeighbourList list(0.0, silodem::max_cohesion_reach(p, cfg.contact, g_abs, 0.0, 0.0));
    list.build(p);
    totals = field->compute(p, list);
    // The wall load is the code's own: put its dumped forces back.
    std::map<std::int64_t, silodem::Vec3> f_of;
    for (const auto& a : frame.atoms) f_of[a.id] = a.f;
    for (std::size_t i = 0; i < p.size(); ++i) p.f[i] = f_of[p.tag[i]];
    if (frames > 0)
      for (std::size_t i = 0; i < p.size(); ++i)
        if (!p.fixed(i) && !seen.count(p.tag[i])) ledger.inject(p.m[i], p.x[i], p.v[i]);
    // Moving walls' work on the grains, from their dumped forces and velocities (trapezoidal rule).
    const double power = silodem::wall_power(p);
    if (frames > 0) ledger.add_wall_work(0.5 * (power_before + power) * double(frame.step - prev_step) * cfg.dt);
    power_before = power;
    for (std::size_t i = 0; i < p.size(); ++i) seen[p.tag[i]] = true;
    if (frames == 0) ledger.start(p, totals, t);
    else ledger.record(p, totals, t, double(frame.step - prev_step) * cfg.dt);
    for (auto& pr : probes) pr->sample(p, t);
    series.row(ledger.state(), p, totals);
    prev_step = frame.step;
    ++frames;
  }
  // The codes dump on multiples of the interval only: a run must hold one, and its last frame must
  // be within one interval of the run's end, or the code stopped early and its result is partial.
  const long every = std::max(1L, cfg.dump_interval_steps);
  const std::string frames_at = " (frames are written on multiples of output.dump_interval_steps = " +
                                std::to_string(every) + "; the run covers steps " + std::to_string(tr.start_step) +
                                " to " + std::to_string(tr.steps) + ")";
  if (frames == 0) throw std::runtime_error("dump " + dump.string() + " holds no frame" + frames_at);
  if (tr.steps - prev_step >= every)
    throw std::runtime_error("dump " + dump.string() + " ends at step " + std::to_string(prev_step) +
                             ": the code stopped before the run's end" + frames_at);
  json digest = json::object();
  for (const auto& pr : probes) digest[pr->name()] = pr->write(out / "probes");
  const silodem::Vec3 wf = silodem::wall_force_resultant(p);
  double z_top = -INFINITY, mass = 0.0;
  for (std::size_t i = 0; i < p.n_mobile; ++i) z_top = std::max(z_top, p.x[i].z() + p.r[i]), mass += p.m[i];
  json energy = ledger.summary();
  if (rotating) {
    // Rotational kinetic energy is rebuilt from the dumped ω; the springs' energy and the friction
    // laws' dissipation need per-contact history the dump does not hold: the ledger is partial and
    // carries no balance (a partial ledger must not look like a closing one).
    for (const char* k : {"elastic_tangential", "elastic_rolling", "friction_dissipated", "balance", "relative_drift",
                          "max_abs_relative_drift"})
      energy.erase(k);
    energy["not_reconstructible"] = {"elastic_tangential", "elastic_rolling", "friction_dissipated"};
    energy["partial"] = "tangential and rolling springs and friction dissipation are not in the dump; elastic is the "
                        "normal springs alone, and there is no balance";
  }
  json summary = {{"format", "silodem-result/1"},
                  {"status", "complete"},
                  {"case", cfg.name},
                  {"seed", cfg.seed},
                  {"derived", {{"dt", cfg.dt}, {"skin", tr.skin}}},
                  {"run", {{"steps", prev_step - tr.start_step}, {"start_step", tr.start_step}, {"time", t}, {"frames", frames}}},
                  {"balls", {{"mobile", p.n_mobile}, {"fixed", p.size() - p.n_mobile}}},
                  {"energy", energy},
                  {"wall_force", {wf.x(), wf.y(), wf.z()}},
                  {"fill", {{"mobile_mass", mass}, {"z_top", p.n_mobile ? z_top : 0.0}}},
                  {"probes", digest},
                  {"reconstructed_from", dump.filename().string()},
                  {"files", {{"series", "series.csv"}, {"probes", "probes/"}}}};
  summary.merge_patch(meta);
  summary["run"]["steps"] = prev_step - tr.start_step;
  summary["run"]["frames"] = frames;
  series.close();
  silodem::write_file_checked(out / "summary.json", summary.dump(2) + "\n");
  silodem::write_manifest(out);  // finished: the harness reads only what its manifest verifies
  return summary;
}

}  // namespace harness
