#pragma once
// Turns a pair's overlap history into contact events (start, end, approach and departure rates).
// Shared by the solver's pair probe and by reference-code adapters that replay dumped traces, so
// every code's restitution and contact duration are measured by the same rule.
#include <vector>

#include "silodem/checkpoint/archive.hpp"

namespace silodem {

struct ContactEvent {
  double t_start = 0.0, t_end = 0.0;   // linearly interpolated between samples
  double rate_in = 0.0;                // dδ/dt just before touching (> 0: approaching)
  double rate_out = 0.0;               // dδ/dt just after the contact ended (< 0: separating)
  double max_overlap = 0.0;
  bool ended = false;
  double duration() const { return t_end - t_start; }
  double restitution() const { return -rate_out / rate_in; }
  void serialize(Archive& a) { a & t_start & t_end & rate_in & rate_out & max_overlap & ended; }
};

class ContactEventDetector {
 public:
  /// With `clamp`, a contact ends when the Kelvin–Voigt force k δ + c dδ/dt reaches zero (the
  /// clamped law's end, docs/theory.md §1b); otherwise when the overlap does (§1a).
  ContactEventDetector(double k, double c, bool clamp) : k_(k), c_(c), clamp_(clamp) {}

  void sample(double t, double delta, double delta_rate);

  const std::vector<ContactEvent>& events() const { return events_; }
  /// Largest gap (−δ) seen after the first contact ended; 0 before.
  double max_gap_after_contact() const { return max_gap_after_; }
  /// Largest gap (−δ) seen at any sample.
  double max_gap() const { return max_gap_; }
  double last_delta() const { return delta_; }
  double last_rate() const { return rate_; }
  void serialize(Archive& a) { a & started_ & in_contact_ & t_ & delta_ & rate_ & max_gap_after_ & max_gap_ & events_; }

 private:
  bool active(double delta, double rate) const { return delta > 0.0 && (!clamp_ || k_ * delta + c_ * rate > 0.0); }
  double k_, c_;
  bool clamp_;
  bool started_ = false, in_contact_ = false;
  double t_ = 0.0, delta_ = 0.0, rate_ = 0.0;
  double max_gap_after_ = 0.0, max_gap_ = 0.0;
  std::vector<ContactEvent> events_;
};

}  // namespace silodem
