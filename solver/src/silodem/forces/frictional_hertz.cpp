// Hertz scenes (forces/frictional_dispatch.hpp).
#include "silodem/forces/frictional_dispatch.hpp"

namespace silodem::frictional {

std::unique_ptr<ForceField> hertz_field(const CaseConfig& cfg) { return with_tangential<false, NormalModel::Hertz, false>(cfg); }

}  // namespace silodem::frictional
