#include "silodem/probes/probe.hpp"

#include <algorithm>

#include "silodem/probes/area_fraction_probe.hpp"
#include "silodem/probes/ball_probe.hpp"
#include "silodem/probes/charge_probe.hpp"
#include "silodem/probes/drops_probe.hpp"
#include "silodem/probes/outflow_probe.hpp"
#include "silodem/probes/pair_probe.hpp"
#include "silodem/probes/section_force_probe.hpp"
#include "silodem/probes/velocity_field_probe.hpp"
#include "silodem/probes/wall_load_probe.hpp"
#include "silodem/probes/wall_pressure_probe.hpp"

namespace silodem {

std::vector<std::unique_ptr<Probe>> make_probes(const CaseConfig& cfg, const SurfaceContacts* surfaces) {
  std::vector<std::unique_ptr<Probe>> out;
  for (const auto& s : cfg.probes) {
    if (s.type == "pair") out.push_back(std::make_unique<PairProbe>(s, cfg.contact.clamp));
    else if (s.type == "ball") out.push_back(std::make_unique<BallProbe>(s, cfg.gravity, cfg.contact.rotation()));
    else if (s.type == "drops") out.push_back(std::make_unique<DropsProbe>(s));
    else if (s.type == "outflow") out.push_back(std::make_unique<OutflowProbe>(s));
    else if (s.type == "section_force") out.push_back(std::make_unique<SectionForceProbe>(s));
    else if (s.type == "velocity_field") out.push_back(std::make_unique<VelocityFieldProbe>(s));
    else if (s.type == "area_fraction") out.push_back(std::make_unique<AreaFractionProbe>(s));
    else if (s.type == "wall_load" && surfaces && !std::any_of(cfg.walls.begin(), cfg.walls.end(), [&](const WallSpec& w) { return w.name == s.wall; }))
      out.push_back(std::make_unique<WallLoadProbe>(s, *surfaces));
    else
      for (const auto& w : cfg.walls)
        if (w.name == s.wall && s.type == "wall_load") out.push_back(std::make_unique<WallLoadProbe>(s, w));
        else if (w.name == s.wall && s.type == "charge") out.push_back(std::make_unique<ChargeProbe>(s, w));
        else if (w.name == s.wall) out.push_back(std::make_unique<WallPressureProbe>(s, w));
  }
  return out;
}

}  // namespace silodem
