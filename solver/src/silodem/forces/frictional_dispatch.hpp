#pragma once
// Internal to the frictional field: from a case's contact options to the one FrictionalLaw
// (forces/frictional_law.hpp) its scene runs. Each family of laws is instantiated in its own file
// (frictional_linear.cpp, frictional_hertz.cpp, frictional_breaking.cpp), which compile side by side.
#include <memory>
#include <stdexcept>

#include "silodem/case/case_config.hpp"
#include "silodem/forces/frictional_law.hpp"

namespace silodem::frictional {

template <bool Brk, NormalModel N, TangentialModel T, RollingModel R, bool Coh>
std::unique_ptr<ForceField> with_clamp(const CaseConfig& cfg) {
  auto table = contact::pair_table(cfg);
  const double pn_g = cfg.contact.p_n * cfg.gravity.norm();
  const double arm = cfg.contact.slip_arm_radius ? 0.0 : 0.5;
  const bool lim = cfg.contact.rolling_limit_with_dashpot;
  const bool secant = cfg.breakage && cfg.breakage->secant_energy;
  if (cfg.contact.clamp)
    return std::make_unique<PairLoop<FrictionalLaw<N, T, R, true, Coh, Brk>>>(FrictionalLaw<N, T, R, true, Coh, Brk>(std::move(table), cfg.dt, pn_g, arm, lim, secant));
  return std::make_unique<PairLoop<FrictionalLaw<N, T, R, false, Coh, Brk>>>(FrictionalLaw<N, T, R, false, Coh, Brk>(std::move(table), cfg.dt, pn_g, arm, lim, secant));
}

template <bool Brk, NormalModel N, TangentialModel T, bool Coh>
std::unique_ptr<ForceField> with_rolling(const CaseConfig& cfg) {
  if (cfg.contact.rolling == RollingModel::ConstantTorque) return with_clamp<Brk, N, T, RollingModel::ConstantTorque, Coh>(cfg);
  if (cfg.contact.rolling == RollingModel::Spring) return with_clamp<Brk, N, T, RollingModel::Spring, Coh>(cfg);
  return with_clamp<Brk, N, T, RollingModel::None, Coh>(cfg);
}

template <bool Brk, NormalModel N, bool Coh>
std::unique_ptr<ForceField> with_tangential(const CaseConfig& cfg) {
  switch (cfg.contact.tangential) {
    case TangentialModel::None: return with_rolling<Brk, N, TangentialModel::None, Coh>(cfg);
    case TangentialModel::CoulombSliding: return with_rolling<Brk, N, TangentialModel::CoulombSliding, Coh>(cfg);
    case TangentialModel::LinearHistory: return with_rolling<Brk, N, TangentialModel::LinearHistory, Coh>(cfg);
    case TangentialModel::Mindlin:
      if constexpr (N == NormalModel::Hertz) return with_rolling<Brk, N, TangentialModel::Mindlin, Coh>(cfg);
      break;
  }
  throw std::logic_error("no such tangential law with this normal law");
}

/// The linear law's scenes (with or without the paper's cohesion), Hertz scenes, and Hertz scenes with breakage.
std::unique_ptr<ForceField> linear_field(const CaseConfig& cfg);
std::unique_ptr<ForceField> hertz_field(const CaseConfig& cfg);
std::unique_ptr<ForceField> breaking_field(const CaseConfig& cfg);

}  // namespace silodem::frictional
