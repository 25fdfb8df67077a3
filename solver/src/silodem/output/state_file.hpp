#pragma once
// The state of a run at one instant, as case balls (docs/case-format.md "balls"): every ball that
// exists then — mobile and fixed, wall balls included, ids kept — with full-precision positions
// and velocities. A run writes its final state (state.json); `continuation` turns a state back into
// a case that carries on from it, which is how every code starts discharge and closure from one
// identical filled state (docs/reference-codes.md).
#include <filesystem>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/case/json_reader.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

struct StateSnapshot {
  std::string case_name;
  long step = 0;      // steps of length dt since t = 0
  double time = 0.0;  // = step · dt
  double dt = 0.0;
  std::vector<BallSpec> balls;  // in tag order
};

/// The fields both state formats start with: case, step, time, dt (step ≥ 0, dt > 0 checked).
StateSnapshot read_state_header(const JsonReader& r);

/// Whether every position and velocity is finite (JSON has no NaN: nlohmann would write null).
bool state_is_finite(const Particles& p);

/// Writes the state atomically (temporary file, then rename). Refuses a state that is not finite
/// (std::logic_error: the guards stop a run before its state gets there).
void write_state(const std::filesystem::path& file, const CaseConfig& cfg, const Particles& p,
                 const std::vector<std::string>& material_names, long step, double t);

/// A run's state files in `dir`: state.sds (compact, output/state_binary.hpp) always, and
/// state.json unless the case's output.state_json is false.
void write_states(const std::filesystem::path& dir, const CaseConfig& cfg, const Particles& p,
                  const std::vector<std::string>& material_names, long step, double t);
/// The state file a run's summary names first: "state.json", or "state.sds" without it.
std::string state_file_name(const CaseConfig& cfg);

/// Reads a state file, compact or JSON (told apart by the first bytes); throws CaseError naming the path and the field on malformed input.
StateSnapshot read_state(const std::filesystem::path& file);

/// The case `cfg` continued from `s`: its balls are the state's, time starts at s.step · dt, events
/// that ran before are done. Throws CaseError if the state does not fit the case (different time
/// step, a material the case lacks, a state later than the duration).
/// What a state does not hold: the drop feeder's queue and random sequence (a recycling run
/// continues physically alike but not bitwise), and the energy ledger (it restarts from the state).
CaseConfig continuation(const CaseConfig& cfg, const StateSnapshot& s);

}  // namespace silodem
