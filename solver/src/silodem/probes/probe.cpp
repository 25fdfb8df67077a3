#include "silodem/probes/probe.hpp"

#include "silodem/probes/ball_probe.hpp"
#include "silodem/probes/drops_probe.hpp"
#include "silodem/probes/pair_probe.hpp"

namespace silodem {

std::vector<std::unique_ptr<Probe>> make_probes(const CaseConfig& cfg) {
  std::vector<std::unique_ptr<Probe>> out;
  for (const auto& s : cfg.probes) {
    if (s.type == "pair") out.push_back(std::make_unique<PairProbe>(s, cfg.contact.clamp));
    else if (s.type == "ball") out.push_back(std::make_unique<BallProbe>(s, cfg.gravity));
    else out.push_back(std::make_unique<DropsProbe>(s));
  }
  return out;
}

}  // namespace silodem
