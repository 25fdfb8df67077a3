// LAMMPS (Debian `lammps`, 29 Sep 2021): the only file that knows LAMMPS.
// Mapping (facts verified in docs/reference-codes.md, Measured facts: LAMMPS):
//  - Kelvin–Voigt with constant k, c: `pair_style granular`, `hooke k c ... damping velocity`
//    (force k δ + c δ̇, c in N s/m, not mass-scaled). Mixing is geometric by default, so every
//    type pair gets an explicit pair_coeff with the series values (11).
//  - frictionless: `tangential linear_nohistory 0 0`.
//  - clamp: `limit_damping` (LAMMPS's default does not clamp, like the paper).
//  - wall balls: own types, not integrated, gravity on the mobile group only, wall–wall pairs
//    excluded from the neighbour list; the wall load is their per-atom force.
//  - integration: fix nve/sphere — velocity Verlet, the dashpot sees the half-step velocity.
//  - stages: gate balls deleted by id, leavers by `fix evaporate` in the region below the outflow
//    height, closure by taking the slab's mobile balls out of the integrated group.
#include <cstdio>
#include <fstream>

#include "harness/backends/reference_backend.hpp"
#include "harness/backends/subprocess.hpp"

namespace harness {

namespace {

const auto fmt = full_precision;

class LammpsBackend final : public ReferenceBackend {
 public:
  std::string code() const override { return "lammps"; }
  std::string missing() const override { return find_on_path("lmp").empty() ? "lmp not found on PATH" : ""; }

 protected:
  std::string code_limits(const silodem::CaseConfig&) const override { return ""; }

  std::string version(const std::filesystem::path& log) const override {
    std::ifstream in(log);
    std::string l;
    while (std::getline(in, l))
      if (l.rfind("LAMMPS (", 0) == 0) return l;
    return "unknown";
  }

 public:
  Input write_input(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    const TypeGroups groups = lammps_type_groups(tr);
    std::string d;
    d += "# silodem case \"" + cfg.name + "\" translated for LAMMPS\n";
    d += "units si\natom_style sphere\natom_modify map array\nboundary m m m\nnewton off\ncomm_modify vel yes\n";
    d += "read_data data.lmp\n";
    if (tr.start_step > 0) d += "reset_timestep " + std::to_string(tr.start_step) + "\n";
    d += "group mobile type" + groups.mobile + "\n";
    if (!groups.wall.empty()) d += "group wall type" + groups.wall + "\n";
    d += "pair_style granular\n";
    for (std::size_t a = 1; a <= tr.types.size(); ++a)
      for (std::size_t b = a; b <= tr.types.size(); ++b) {
        const int ia = int(a), ib = int(b);
        d += "pair_coeff " + std::to_string(a) + " " + std::to_string(b) + " hooke " + fmt(tr.pair_k(ia, ib)) + " " +
             fmt(tr.pair_c(ia, ib)) + " tangential linear_nohistory 0 0 damping velocity" +
             (cfg.contact.clamp ? " limit_damping" : "") + "\n";
      }
    d += "neighbor " + fmt(tr.skin) + " bin\nneigh_modify delay 0 every 1 check yes" + groups.exclusions + "\n";
    d += "timestep " + fmt(cfg.dt) + "\n";
    d += lammps_family_motion(cfg, tr, "dump_modify d sort id format float %.17g", OutflowStyle::Evaporate);
    return lammps_family_input("lmp", "in.lammps", d, tr);
  }
};

}  // namespace

std::unique_ptr<Backend> make_lammps_backend() { return std::make_unique<LammpsBackend>(); }

}  // namespace harness
