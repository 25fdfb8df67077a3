// Hertz scenes with breakage (forces/frictional_dispatch.hpp, docs/model.md §14).
#include "silodem/forces/frictional_dispatch.hpp"

namespace silodem::frictional {

std::unique_ptr<ForceField> breaking_field(const CaseConfig& cfg) { return with_tangential<true, NormalModel::Hertz, false>(cfg); }

}  // namespace silodem::frictional
