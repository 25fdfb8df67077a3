#include "silodem/run/run_state.hpp"

#include <cstddef>

namespace silodem {

void serialize_run(Archive& a, RunParts& r) {
  a & r.files & r.step & r.next_row & r.corrector_passes_total & r.evaluations & r.corrector_passes_max &
      r.corrector_residual_max;
  // Numbers only. The friction sums only in a rotating scene, so a frictionless checkpoint keeps
  // its layout; the particles are those of the case, so a reader knows which it is before reading.
  a.raw(&r.totals, offsetof(ForceTotals, elastic_tangential));
  if (r.p.rotating) a & r.totals.elastic_tangential & r.totals.elastic_rolling & r.totals.p_friction & r.totals.sliding;
  a & r.p;
  r.list.serialize(a, r.p);  // after the balls: its indices are checked against them
  r.field.serialize_history(a, r.list);
  if (r.surfaces) r.surfaces->serialize(a);
  r.integrator.serialize(a, r.p);
  a & r.ledger & r.stages & r.guards;
  bool has_feeder = r.feeder != nullptr;
  a & has_feeder;
  if (has_feeder != (r.feeder != nullptr)) throw CheckpointError("checkpoint was written for a case with another drop setting");
  if (r.feeder) a & *r.feeder;
  bool has_breakage = r.breakage != nullptr;
  a & has_breakage;
  if (has_breakage != (r.breakage != nullptr)) throw CheckpointError("checkpoint was written for a case with another breakage setting");
  if (r.breakage) a & *r.breakage;
  std::uint64_t n_probes = r.probes.size();
  a & n_probes;
  if (n_probes != r.probes.size()) throw CheckpointError("checkpoint was written for a case with other probes");
  for (auto& pr : r.probes) {
    std::string name = pr->name();
    a & name;
    if (name != pr->name()) throw CheckpointError("checkpoint holds probe \"" + name + "\" where the case has \"" + pr->name() + "\"");
    a & *pr;
  }
}

}  // namespace silodem
