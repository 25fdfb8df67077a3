#include "silodem/probes/contact_events.hpp"

#include <algorithm>

namespace silodem {

void ContactEventDetector::sample(double t, double delta, double rate) {
  const bool now = active(delta, rate);
  if (started_) {
    if (now && !in_contact_) {
      ContactEvent e;
      e.t_start = delta_ < 0.0 ? t_ + (t - t_) * (-delta_) / (delta - delta_) : t_;
      e.rate_in = rate_;
      events_.push_back(e);
    } else if (!now && in_contact_) {
      ContactEvent& e = events_.back();
      if (delta <= 0.0) {
        e.t_end = t_ + (t - t_) * delta_ / (delta_ - delta);
      } else {  // clamped: the force crossed zero while still overlapping
        const double f0 = k_ * delta_ + c_ * rate_, f1 = k_ * delta + c_ * rate;
        e.t_end = t_ + (t - t_) * f0 / (f0 - f1);
      }
      e.rate_out = rate;
      e.ended = true;
    }
  } else if (now) {  // already in contact at the first sample
    ContactEvent e;
    e.t_start = t;
    e.rate_in = rate;
    events_.push_back(e);
  }
  if (now) events_.back().max_overlap = std::max(events_.back().max_overlap, delta);
  if (!events_.empty() && events_.front().ended && !now) max_gap_after_ = std::max(max_gap_after_, -delta);
  max_gap_ = std::max(max_gap_, -delta);
  started_ = true;
  in_contact_ = now;
  t_ = t;
  delta_ = delta;
  rate_ = rate;
}

}  // namespace silodem
