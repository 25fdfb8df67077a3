#include "silodem/case/hertz_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "silodem/contact/hertz_constants.hpp"
#include "silodem/contact/pair_table.hpp"
#include "silodem/contact/stiffest_pair.hpp"
#include "silodem/contact/tangential.hpp"

namespace silodem {

namespace {
/// Six significant figures, as a person reads them (20, not format_number's shortest 2e+01).
std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}
}  // namespace

SceneSpeed largest_speed(const CaseConfig& cfg) {
  SceneSpeed s;
  const double g = cfg.gravity.norm();
  const Vec3 up = g > 0.0 ? Vec3(-cfg.gravity / g) : Vec3::Zero();
  double top = -std::numeric_limits<double>::infinity(), bottom = std::numeric_limits<double>::infinity();
  // Heights of the balls' tops: a ball lands on an obstacle's top, and a large fixed ball used as
  // a plane would otherwise count its centre, far below the scene.
  for (const auto& b : cfg.balls) {
    const double h = b.position.dot(up) + b.radius;
    bottom = std::min(bottom, h);
    if (b.fixed) continue;
    top = std::max(top, h);
    s.initial = std::max(s.initial, b.velocity.norm());
  }
  if (cfg.drops && cfg.drops->count > 0) {
    top = std::max(top, cfg.drops->z0 * up.z() + cfg.drops->r_max);  // drops fall along −z (the loader requires it)
    if (cfg.drops->release) s.initial = std::max(s.initial, cfg.drops->release_speed);
  }
  s.fall_height = g > 0.0 && top > bottom ? top - bottom : 0.0;
  s.speed = std::sqrt(s.initial * s.initial + 2.0 * g * s.fall_height);
  return s;
}

std::vector<ModeLimit> hertz_mode_limits(const CaseConfig& cfg) {
  std::vector<ModeLimit> out;
  const SceneSpeed scene = largest_speed(cfg);
  if (!(scene.speed > 0.0)) return out;
  const contact::PairTable table = contact::pair_table(cfg);
  const bool mindlin = cfg.contact.tangential == TangentialModel::Mindlin;
  const std::string how = "largest initial speed " + num(scene.initial) + " m/s and a free fall over " +
                          num(scene.fall_height) + " m";
  for (const auto& kp : kind_pairs(cfg)) {
    const contact::PairParams& pp = table.at(kp.material_a, kp.material_b);
    const double v = kp.both_mobile ? 2.0 * scene.speed : scene.speed;
    const contact::HertzPeak peak = contact::hertz_peak(kp.m_eff, kp.r_star, pp.e_star, v);
    const double t_c = contact::hertz_contact_time(kp.m_eff, kp.r_star, pp.e_star, v);
    // c = 2ζ√(m* S_n) with S_n the tangent stiffness: at any overlap the linearised contact has
    // the damping ratio ζ itself.
    const auto mode = [&](const char* name, const StabilityLimit& limit, double omega, double zeta,
                          const std::string& stiffness) {
      ModeLimit m;
      m.limit = limit;
      m.pair = kp.description;
      m.detail = std::string(name) + " mode at the peak of an impact at " + num(v) + " m/s (" + how +
                 (kp.both_mobile ? ", doubled for two mobile balls" : "") + "): overlap " +
                 num(peak.overlap) + " m, " + stiffness + ", w = " + num(omega) +
                 " rad/s, zeta = " + num(zeta) + "; the impact lasts t_c = " + num(t_c) +
                 " s, so the limit is " + num(m.limit.dt_max / t_c) + " t_c";
      out.push_back(std::move(m));
    };
    mode("normal", stable_time_step(cfg.integrator, peak.omega, pp.hertz_zeta), peak.omega, pp.hertz_zeta, "k_max = 2 E* sqrt(R* delta) = " + num(peak.stiffness) + " N/m");
    if (mindlin && pp.g_star > 0.0) {
      // Mindlin k_t = 8G*√(R*δ) on the tangential mass 2/7 m* (docs/model.md §10.6); its dashpot
      // γ_t = ρ_γ c_n gives the damping ratio ρ_γ ζ √(7 k_n/(2 k_t)). A history spring loaded by the
      // force law: the tangential limits of theory.md §7.7.
      const double k_t = contact::mindlin_stiffness(pp.g_star, kp.r_star, peak.overlap);
      const double slip = 1.0 + 1.0 / cfg.inertia_factor;  // m*/m_t: 7/2 for spheres, 3 for discs
      const double w_t = std::sqrt(slip * k_t / kp.m_eff);
      const double z_t = pp.shear_damping_ratio * pp.hertz_zeta * std::sqrt(slip * peak.stiffness / k_t);
      mode("Mindlin tangential", stable_tangential_time_step(cfg.integrator, w_t, z_t), w_t, z_t,
           "k_t = 8 G* sqrt(R* delta) = " + num(k_t) + " N/m on m*/" + num(slip));
    }
  }
  return out;
}

}  // namespace silodem
