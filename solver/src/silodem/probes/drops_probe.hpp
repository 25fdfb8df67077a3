#pragma once
// Drops probe: every attempted drop of the filling (Algorithm 2) — where it was released, which
// ball it found first and at what fall height, or why it was rejected.
#include <vector>

#include "silodem/probes/probe.hpp"

namespace silodem {

class DropsProbe final : public Probe {
 public:
  explicit DropsProbe(const ProbeSpec& spec) : Probe(spec.name) {}
  void sample(const Particles&, double) override {}
  void on_drop(const DropRecord& r) override { records_.push_back(r); }
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  std::vector<DropRecord> records_;
};

}  // namespace silodem
