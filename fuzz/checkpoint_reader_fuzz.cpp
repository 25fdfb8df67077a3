// libFuzzer target: arbitrary bytes as a checkpoint. First as a whole file (decode_checkpoint:
// header, length, CRC); a mutated payload never passes the CRC, so the same bytes are also read
// as a bare payload into the parts of a small run (run/run_state.cpp, the order a restart uses),
// and what was restored is then used — the neighbour list, the force loop and every probe.
// Bad bytes must end in a CheckpointError (exit code 2 in the CLI); anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "silodem/case/case_loader.hpp"
#include "silodem/checkpoint/checkpoint_file.hpp"
#include "silodem/core/run_error.hpp"
#include "silodem/fill/drop_feeder.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/run/run_state.hpp"
#include "silodem/scene/scene_builder.hpp"

namespace {

using namespace silodem;

const CaseConfig& fuzz_case() {
  static const CaseConfig cfg = [] {
    std::ifstream in(SILODEM_FUZZ_CASE);
    std::ostringstream s;
    s << in.rdbuf();
    return load_case(nlohmann::json::parse(s.str()));
  }();
  return cfg;
}

/// The parts of a run as run/simulation.cpp makes them, fresh for every input.
struct SmallRun {
  const CaseConfig& cfg = fuzz_case();
  Scene scene = build_scene(cfg);
  NeighbourList list{0.2 * 0.004, 0.0};
  std::unique_ptr<ForceField> field = make_force_field(cfg);
  std::unique_ptr<Integrator> integrator = make_integrator(cfg.integrator, cfg.gravity);
  EnergyLedger ledger{cfg.gravity};
  StageController stages{cfg, ledger};
  RunGuards guards{cfg, scene.particles};
  std::optional<DropFeeder> feeder;
  std::vector<std::unique_ptr<Probe>> probes = make_probes(cfg);
  RunFiles files;
  long step = 0, corrector_passes_total = 0, evaluations = 0;
  double next_row = 0.0, corrector_residual_max = 0.0;
  int corrector_passes_max = 0;
  ForceTotals totals;
  SmallRun() {
    const Material& m = cfg.materials.at(cfg.drops->material);
    feeder.emplace(*cfg.drops, m, scene.material_index(m.name), cfg.gravity, cfg.seed, 1000000);
  }
  void restore(const std::string& payload) {
    Archive a = Archive::reader(payload);
    RunParts parts{files, step, next_row, corrector_passes_total, evaluations, corrector_passes_max,
                   corrector_residual_max, totals, scene.particles, list, *field, nullptr, *integrator, ledger, stages, guards,
                   &*feeder, nullptr, probes};
    serialize_run(a, parts);
    a.expect_end();
    list.update(scene.particles);
    field->compute(scene.particles, list);
    for (auto& pr : probes) pr->sample(scene.particles, double(step) * cfg.dt);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::string payload = bytes;
  try {
    payload = decode_checkpoint(bytes, 0);
  } catch (const CheckpointError&) {
  }
  try {
    SmallRun().restore(payload);
  } catch (const CheckpointError&) {
  } catch (const RunError&) {  // a restored state the force loop refuses (non-finite): exit 3, not a crash
  }
  return 0;
}
