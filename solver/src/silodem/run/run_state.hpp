#pragma once
// Everything one step of a run carries to the next, gathered for a checkpoint (issue 6): the
// balls, the neighbour list in its order, the integrator's ü, the energy ledger, the stages, the
// guards, the drop feeder and every probe, with the loop's counters and where the result files
// stand. One routine lists them for saving and for restoring, so the two cannot drift apart.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "silodem/breakage/breakage_stage.hpp"
#include "silodem/checkpoint/archive.hpp"
#include "silodem/energy/energy_ledger.hpp"
#include "silodem/fill/drop_feeder.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/forces/surface_contacts.hpp"
#include "silodem/integrate/integrator.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/probes/probe.hpp"
#include "silodem/run/guards.hpp"
#include "silodem/run/stages.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

/// Where a checkpointed run writes, and how far (a restart cuts the files back to this).
struct RunFiles {
  std::string partial;  // the temporary result directory
  std::uint64_t series_bytes = 0, dump_bytes = 0;
  bool has_dump = false;
  double wall_seconds = 0.0;  // used by the run up to the checkpoint
  void serialize(Archive& a) { a & partial & series_bytes & dump_bytes & has_dump & wall_seconds; }
};

/// References to the parts of a run (run/simulation.cpp owns them).
struct RunParts {
  RunFiles& files;
  long& step;
  double& next_row;  // time of the next series row
  long& corrector_passes_total;
  long& evaluations;
  int& corrector_passes_max;
  double& corrector_residual_max;
  ForceTotals& totals;
  Particles& p;
  NeighbourList& list;
  ForceField& field;  // its per-contact history
  SurfaceContacts* surfaces;  // the smooth walls' springs; null without smooth walls
  Integrator& integrator;
  EnergyLedger& ledger;
  StageController& stages;
  RunGuards& guards;
  DropFeeder* feeder;  // null without drops
  BreakageStage* breakage;  // null without breakage
  std::vector<std::unique_ptr<Probe>>& probes;
};

/// Saves or restores (by the archive's direction) every part; restoring checks what it reads.
void serialize_run(Archive& a, RunParts& r);

}  // namespace silodem
