#include "silodem/contact/hertz_constants.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace silodem::contact {

double hertz_restitution(double zeta, bool clamp) {
  const double b = 2.0 * std::sqrt(1.5) * zeta;
  // x'' = −x^{3/2} − b x^{1/4} x'; x is clamped at 0 in the powers (RK4 sub-stages may cross it).
  const auto acc = [b](double x, double v) {
    const double xp = x > 0.0 ? x : 0.0;
    return -xp * std::sqrt(xp) - b * std::sqrt(std::sqrt(xp)) * v;
  };
  const double h = 2e-5;  // the undamped contact lasts τ ≈ 3.22
  double x = 0.0, v = 1.0;
  for (long k = 0; k < 100000000; ++k) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    const double x1 = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    const double v1 = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    if (clamp && v1 < 0.0) {
      // The force x^{3/2} + b x^{1/4} v reaches zero: x^{5/4} = −b v.
      const double f1 = x1 * std::sqrt(x1) + b * std::sqrt(std::sqrt(x1)) * v1;
      if (!(f1 > 0.0)) {
        const double f0 = x * std::sqrt(x) + b * std::sqrt(std::sqrt(x)) * v;
        const double s = f0 / (f0 - f1);  // linear in the step: the error is O(h²) on e
        return -(v + s * (v1 - v));
      }
    }
    if (!(x1 > 0.0) && k > 0) {
      const double s = x / (x - x1);
      return -(v + s * (v1 - v));
    }
    x = x1;
    v = v1;
    if (v > 0.0 && x <= 0.0 && k > 10) return 0.0;  // never rebounds
  }
  throw std::runtime_error("hertz_restitution: the contact did not end");
}

double hertz_damping_ratio_for_restitution(double e, bool clamp) {
  if (!(e > 0.0 && e <= 1.0)) throw std::invalid_argument("restitution must be in (0, 1]");
  if (e == 1.0) return 0.0;
  // A bisection of about 35 integrations (a tenth of a second): kept per (e, clamp), since every
  // load of a case asks again (a compare job prepares its case anew) and the answer is the same bits.
  static std::mutex guard;
  static std::map<std::pair<double, bool>, double> known;
  {
    const std::lock_guard<std::mutex> lock(guard);
    if (const auto it = known.find({e, clamp}); it != known.end()) return it->second;
  }
  double lo = 0.0, hi = 0.05;
  while (hertz_restitution(hi, clamp) > e) hi *= 2.0;
  while (hi - lo > 1e-10 * hi) {
    const double mid = 0.5 * (lo + hi);
    (hertz_restitution(mid, clamp) > e ? lo : hi) = mid;
  }
  const std::lock_guard<std::mutex> lock(guard);
  return known[{e, clamp}] = 0.5 * (lo + hi);
}

double hertz_contact_time(double m_eff, double r_star, double e_star, double speed) {
  return 2.9432 * std::pow(15.0 / 16.0, 0.4) * std::pow(m_eff * m_eff / (r_star * e_star * e_star * speed), 0.2);
}

HertzPeak hertz_peak(double m_eff, double r_star, double e_star, double speed) {
  HertzPeak p;
  p.overlap = std::pow(15.0 * m_eff * speed * speed / (16.0 * e_star * std::sqrt(r_star)), 0.4);
  p.stiffness = 2.0 * e_star * std::sqrt(r_star * p.overlap);
  p.omega = std::sqrt(p.stiffness / m_eff);
  return p;
}

}  // namespace silodem::contact
