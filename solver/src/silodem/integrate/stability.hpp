#pragma once
// The largest time step at which a scheme stays stable on one linear spring–dashpot contact
// (ω0 = √(k/m_eff), ζ = c/(2√(k m_eff))). A case whose Δt exceeds it for its stiffest pair is
// refused at load time: every such run blows up, and the loader can say why.
#include "silodem/case/case_config.hpp"

namespace silodem {

struct StabilityLimit {
  double dt_max;         // s
  const char* rule;      // the bound used, for the refusal message
};

/// Necessary, not sufficient: a ball squeezed between several contacts oscillates faster than
/// one pair, so a Δt just below this limit can still be unstable in a dense packing.
StabilityLimit stable_time_step(const IntegratorSpec& in, double omega0, double zeta);

}  // namespace silodem
