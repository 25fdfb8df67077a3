// This solver as a backend: runs in process and writes its result files directly. With dumps
// enabled it also rebuilds its ledger from its own dump (into reconstructed/), so the comparator
// can hold the solver's ledger against the same reconstruction every reference code gets.
#include <algorithm>

#include "harness/backends/backend.hpp"
#include "harness/backends/translation.hpp"
#include "harness/trace/reconstruct.hpp"
#include "silodem/output/manifest.hpp"
#include "silodem/run/simulation.hpp"

namespace harness {

namespace {

class SilodemBackend final : public Backend {
 public:
  std::string code() const override { return "silodem"; }
  std::string not_representable(const silodem::CaseConfig&) const override { return ""; }
  std::string missing() const override { return ""; }
  void set_progress_every(double every) override { progress_every_ = every; }
  BackendResult run(const silodem::CaseConfig& cfg, const std::filesystem::path& dir, double) const override {
    try {
      silodem::RunOptions run{dir, progress_every_ >= 0.0, false};
      run.progress_every = std::max(0.0, progress_every_);
      silodem::run_case(cfg, run);
      // With breakage the dump's balls change at every break (fragments with new tags), which the
      // rebuild from frames does not follow: no reconstruction, so no ledger comparison either.
      if (cfg.dump_interval_steps > 0 && !cfg.breakage) {
        std::string reason;
        const Translation tr = translate(cfg, reason);
        if (reason.empty()) {
          reconstruct_result(cfg, tr, dir / "dump.txt", dir / "reconstructed", {{"code", "silodem"}});
          silodem::write_manifest(dir);  // the directory now holds the reconstruction too
        }
      }
    } catch (const std::exception& e) {
      return {BackendResult::Status::Failed, e.what(), dir};
    }
    return {BackendResult::Status::Ran, "", dir};
  }

 private:
  double progress_every_ = -1.0;
};

}  // namespace

std::unique_ptr<Backend> make_silodem_backend() { return std::make_unique<SilodemBackend>(); }

std::vector<std::unique_ptr<Backend>> all_backends() {
  std::vector<std::unique_ptr<Backend>> v;
  v.push_back(make_silodem_backend());
  v.push_back(make_lammps_backend());
  v.push_back(make_liggghts_backend());
  v.push_back(make_yade_backend());
  return v;
}

}  // namespace harness
