#pragma once
// The contact law of scenes with friction, rotation, rolling resistance or Hertz contacts
// (docs/model.md §10). The sub-models are template parameters chosen once per scene, so the loop
// (forces/pair_loop.hpp, shared with the paper's law) holds no per-contact dispatch.
#include <memory>

#include "silodem/case/case_config.hpp"
#include "silodem/forces/force_field.hpp"

namespace silodem {

std::unique_ptr<ForceField> make_frictional_field(const CaseConfig& cfg);

}  // namespace silodem
