#pragma once
// Pair probe: every contact between two named balls (onset, end, rates, restitution, peak
// overlap), plus the pair's final gap and largest gap after the first contact (cohesion capture).
#include <optional>

#include "silodem/probes/contact_events.hpp"
#include "silodem/probes/probe.hpp"

namespace silodem {

class PairProbe final : public Probe {
 public:
  PairProbe(const ProbeSpec& spec, bool clamp);
  void sample(const Particles& p, double t) override;
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  std::string a_, b_;
  bool clamp_;
  std::uint64_t topology_ = ~std::uint64_t(0);
  std::size_t i_ = 0, j_ = 0;
  std::optional<ContactEventDetector> detector_;
  double k_ = 0.0, c_ = 0.0;
};

}  // namespace silodem
