#pragma once
// Outflow probe: every ball that left through the outlet (time, id, mass) — the discharge's mass
// flow rate comes from its cumulative mass against time.
#include <vector>

#include "silodem/probes/probe.hpp"

namespace silodem {

class OutflowProbe final : public Probe {
 public:
  explicit OutflowProbe(const ProbeSpec& spec) : Probe(spec.name) {}
  void sample(const Particles&, double) override {}
  void on_exit(const ExitRecord& e) override { exits_.push_back(e); }
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  std::vector<ExitRecord> exits_;
};

}  // namespace silodem
