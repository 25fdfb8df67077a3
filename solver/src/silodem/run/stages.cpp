#include "silodem/run/stages.hpp"

#include "silodem/checkpoint/archive.hpp"

#include <algorithm>
#include <cmath>

namespace silodem {

StageController::StageController(const CaseConfig& cfg, EnergyLedger& ledger)
    : cfg_(cfg), ledger_(ledger), done_(cfg.events.size()) {
  // A continuation starts at step S: an event ran before it if a step s < S applied it (apply()
  // runs at the top of each step with t = s·dt), i.e. if (S − 1)·dt reached its time.
  if (cfg.start_step > 0)
    for (std::size_t e = 0; e < cfg.events.size(); ++e)
      done_[e] = double(cfg.start_step - 1) * cfg.dt + 1e-15 >= cfg.events[e].time;
}

bool StageController::apply(Particles& p, long step, double t, DropFeeder* feeder) {
  bool changed = false;
  // A continuation's state holds where its moving walls are, not that they move: the move_wall
  // events that ran before it set their velocities again, in time order.
  if (!replayed_) {
    replayed_ = true;
    std::vector<const StageEvent*> ran;
    for (std::size_t e = 0; e < cfg_.events.size(); ++e)
      if (done_[e] && cfg_.events[e].type == "move_wall") ran.push_back(&cfg_.events[e]);
    std::stable_sort(ran.begin(), ran.end(), [](const auto* a, const auto* b) { return a->time < b->time; });
    for (const StageEvent* ev : ran)
      for (std::size_t i = p.n_mobile; i < p.size(); ++i)
        if (ev->names(p.id[i])) p.v[i] = ev->velocity;
    if (!ran.empty()) p.refresh_moving_walls(), changed = true;
  }
  for (std::size_t e = 0; e < cfg_.events.size(); ++e) {
    const StageEvent& ev = cfg_.events[e];
    if (done_[e] || t + 1e-15 < ev.time) continue;
    done_[e] = true;
    if (ev.type == "open_outlet") {
      // The balls that close the outlet become mobile (the paper's discharge), at rest — or are
      // taken away, the default (see StageEvent::release_mobile).
      const std::string prefix = ev.wall + "_";
      std::vector<std::string> gate;
      for (std::size_t i = p.n_mobile; i < p.size(); ++i)
        if (p.id[i].rfind(prefix, 0) == 0) gate.push_back(p.id[i]);
      for (const auto& id : gate) {
        const std::size_t j = p.make_mobile(std::size_t(p.find(id)));
        p.v[j].setZero();
        if (ev.release_mobile) ledger_.inject(p.m[j], p.x[j], p.v[j]);
        else p.remove_mobile(j);
        changed = true;
      }
    } else if (ev.type == "move_wall") {
      // A moving wall: its balls that are still fixed carry the velocity (the contact laws read it),
      // and WallMotion::advance() moves them each step. Forces are evaluated again with it.
      for (std::size_t i = p.n_mobile; i < p.size(); ++i)
        if (ev.names(p.id[i])) p.v[i] = ev.velocity;
      p.refresh_moving_walls();
      changed = true;
    } else {
      // Sudden closure: every mobile ball whose centre lies in the outlet slab is stopped and fixed.
      for (std::size_t i = p.n_mobile; i-- > 0;) {
        const Vec3 d = p.x[i] - ev.centre;
        if (std::abs(d.z()) > 0.5 * ev.thickness || std::hypot(d.x(), d.y()) > 0.5 * ev.diameter) continue;
        ledger_.withdraw_ball(p, i);
        p.make_fixed(i);
        ++converted_;
        changed = true;
      }
    }
  }
  // Looked for only every every_steps steps when a comparison asks for it: the reference codes
  // delete leavers periodically (LAMMPS fix evaporate, LIGGGHTS run ... every, YADE's driver), and
  // a leaver that falls on below the outlet until then can still collide with the stream.
  if (cfg_.outflow.enabled && step % cfg_.outflow.every_steps == 0) {
    for (std::size_t i = p.n_mobile; i-- > 0;) {
      if (p.x[i].z() >= cfg_.outflow.below_z) continue;
      exits_.push_back({t, p.id[i], p.m[i], p.x[i]});
      ledger_.withdraw_ball(p, i);
      if (cfg_.outflow.recycle && feeder) feeder->recycle(p.ball(i));
      p.remove_mobile(i);
      changed = true;
    }
  }
  return changed;
}

void ExitRecord::serialize(Archive& a) { a & t & id & mass & x; }

void StageController::serialize(Archive& a) {
  a & done_ & converted_;
  if (a.loading() && done_.size() != cfg_.events.size())
    throw CheckpointError("checkpoint payload is damaged (another number of stage events)");
  if (a.loading()) replayed_ = true;  // the checkpoint's wall balls carry their velocities
}

}  // namespace silodem
