// The linear law's frictional scenes, with and without the paper's cohesion (forces/frictional_dispatch.hpp).
#include "silodem/forces/frictional_dispatch.hpp"

namespace silodem::frictional {

std::unique_ptr<ForceField> linear_field(const CaseConfig& cfg) {
  if (cfg.contact.cohesion) return with_tangential<false, NormalModel::Linear, true>(cfg);
  return with_tangential<false, NormalModel::Linear, false>(cfg);
}

}  // namespace silodem::frictional
