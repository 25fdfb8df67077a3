#include "silodem/forces/frictional_field.hpp"

#include <stdexcept>

#include "silodem/forces/frictional_dispatch.hpp"

namespace silodem {

std::unique_ptr<ForceField> make_frictional_field(const CaseConfig& cfg) {
  if (!(cfg.dt > 0.0)) throw std::invalid_argument("the frictional force field needs the time step");
  if (cfg.contact.onset_correction) throw std::invalid_argument("the onset correction is not available with friction or Hertz contacts");
  if (cfg.breakage && cfg.contact.normal != NormalModel::Hertz)
    throw std::invalid_argument("breakage is built on Hertz contacts (seed 003's law)");
  if (cfg.contact.normal == NormalModel::Hertz) {
    if (cfg.contact.cohesion) throw std::invalid_argument("the paper's cohesion needs its linear law's k_ij, not Hertz");
    return cfg.breakage ? frictional::breaking_field(cfg) : frictional::hertz_field(cfg);
  }
  return frictional::linear_field(cfg);
}

std::unique_ptr<ForceField> make_force_field(const CaseConfig& cfg) {
  if (cfg.contact.frictionless_linear()) return make_force_field(cfg.contact, cfg.gravity.norm(), cfg.dt);
  return make_frictional_field(cfg);
}

}  // namespace silodem
