#pragma once
// The force loop of scenes with friction, rotation, rolling resistance or Hertz contacts
// (docs/model.md §10). The sub-models are template parameters chosen once per scene, so the loop
// holds no per-contact dispatch; the paper's frictionless law keeps its own loop
// (forces/force_field.cpp), untouched by any of this.
#include <memory>

#include "silodem/case/case_config.hpp"
#include "silodem/forces/force_field.hpp"

namespace silodem {

std::unique_ptr<ForceField> make_frictional_field(const CaseConfig& cfg);

}  // namespace silodem
