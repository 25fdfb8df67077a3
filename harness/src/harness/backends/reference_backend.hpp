#pragma once
// What the LAMMPS, LIGGGHTS and YADE backends share: translate the case, write the code's input,
// run it as a subprocess with a time limit, and rebuild the result files from its dump. A crash or
// time-out becomes a "failed" summary carrying the tail of the code's log.
#include <nlohmann/json.hpp>

#include <utility>

#include "harness/backends/backend.hpp"
#include "harness/backends/translation.hpp"

namespace harness {

class ReferenceBackend : public Backend {
 public:
  std::string not_representable(const silodem::CaseConfig& cfg) const override;
  BackendResult run(const silodem::CaseConfig& cfg, const std::filesystem::path& dir,
                    double time_limit_s) const override;

  struct Input {
    std::vector<std::pair<std::string, std::string>> files;  // (name, content) written to the work dir
    std::string main_file;                                   // echoed into the summary as "input"
    std::vector<std::string> argv;
    std::vector<std::string> env;
  };
  /// The code's input for a case (also what the tests inspect), from `translation`.
  virtual Input write_input(const silodem::CaseConfig& cfg, const Translation& tr) const = 0;
  /// The case translated for this code: translate() turned into the code's axes (frame()).
  Translation translation(const silodem::CaseConfig& cfg, std::string& reason) const;

 protected:
  Parallel parallel_;  // set by a code that runs under MPI (the LAMMPS family)
  /// The launcher's words before the code's argv for parallel_ (none for one rank).
  std::vector<std::string> launch_prefix() const;
  /// set_parallel for an MPI code (the LAMMPS family): any rank count, mpirun or srun on PATH.
  std::string set_mpi_parallel(const Parallel& p);
  /// The LAMMPS family's decomposition on more than one rank, before read_data: never across the
  /// vertical (z; y in the planar frame), where a silo's grains settle at the bottom (the codes'
  /// default split of the tallest axis leaves upper ranks idle; measured in docs/cluster.md).
  std::string decomposition(const silodem::CaseConfig& cfg) const;
  virtual std::string version(const std::filesystem::path& log) const = 0;
  /// Code-specific limits on top of the shared ones (cohesion, timed drops, integrator), given the
  /// case's translation (its types and pair constants), made once by not_representable.
  virtual std::string code_limits(const silodem::CaseConfig& cfg, const Translation& tr) const = 0;
  /// The code's axes against silodem's (planar_frame.hpp); the identity unless a code needs a turn.
  virtual silodem::Mat3 frame(const silodem::CaseConfig&) const { return silodem::Mat3::Identity(); }
};

/// Dump interval the reference runs use (the case's, at least 1).
long dump_interval(const silodem::CaseConfig& cfg);

/// A LAMMPS/LIGGGHTS data file (atom_style sphere/granular: id type diameter density x y z).
std::string lammps_data_file(const Translation& tr);

/// A number with all 17 significant digits, as the decks carry them.
std::string full_precision(double x);

/// How leavers are deleted, every stages.outflow.every_steps steps, as silodem does then (an exit is
/// seen up to that late, in every code alike): LAMMPS by `fix evaporate`; LIGGGHTS has none, so its
/// run is cut into segments with `delete_atoms` between them (each segment's setup recomputes forces
/// once with the full-step velocity: a dashpot difference of c·a·Δt/2 at that step); YADE's driver
/// erases them from Python. translation.cpp refuses intervals under kMinOutflowEvery: fix evaporate
/// every step costs 10× the run and LIGGGHTS would run one segment per step.
enum class OutflowStyle { Evaporate, DeleteEvery };

/// What LAMMPS and LIGGGHTS decks share after the contact law: gravity on the mobile group only,
/// NVE (velocity Verlet, the fix style `integrate`) on it, the dump every backend reads (`dump_modify`
/// given per code), thermo, and the run cut at each stage event (translation.hpp) with the event's
/// commands between.
std::string lammps_family_motion(const silodem::CaseConfig& cfg, const Translation& tr,
                                 const std::string& dump_modify, OutflowStyle outflow,
                                 const std::string& integrate = "nve/sphere");

/// What LAMMPS's and LIGGGHTS's `fix move` cannot carry of the walls' laws ("" if nothing): one
/// style per group, so a turn with an oscillation; and a turn that starts after t = 0 (rotate turns
/// from the step the fix is defined).
std::string fix_move_limits(const Translation& tr);

/// The run of a LAMMPS-family deck: the deck and the data file, `exe -in <deck_file>` without log.
ReferenceBackend::Input lammps_family_input(const std::string& exe, const std::string& deck_file,
                                            const std::string& deck, const Translation& tr);

/// Type lists " 1 3" of the mobile and the wall types, and the wall–wall neighbour exclusions.
struct TypeGroups {
  std::string mobile, wall, exclusions;
};
TypeGroups lammps_type_groups(const Translation& tr);

}  // namespace harness
