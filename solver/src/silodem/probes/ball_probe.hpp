#pragma once
// Ball probe: the apexes of one ball's trajectory (local maxima of height) and its final state —
// the rebound heights of the free-fall case, and the slip and spin of the friction cases. With a
// `from_time`, also its state when the window opens and its mean position over the window (the
// momentum balances of a ball in a moving vessel).
#include <vector>

#include "silodem/probes/probe.hpp"

namespace silodem {

class BallProbe final : public Probe {
 public:
  /// `rotating`: the scene's balls rotate; the final angular velocity is then reported too.
  BallProbe(const ProbeSpec& spec, const Vec3& gravity, bool rotating = false);
  void sample(const Particles& p, double t) override;
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  std::string id_;
  Vec3 up_;          // −g/|g|
  double g_abs_;
  std::uint64_t topology_ = ~std::uint64_t(0);
  std::size_t i_ = 0;
  bool started_ = false;
  double t_prev_ = 0.0, h_prev_ = 0.0, w_prev_ = 0.0;  // height and vertical speed along `up_`
  std::vector<std::pair<double, double>> apexes_;     // (t, height)
  Vec3 x_last_ = Vec3::Zero(), v_last_ = Vec3::Zero();
  bool rotating_;
  Vec3 w_last_ = Vec3::Zero();
  double from_time_;                 // > 0: the window's start
  long window_samples_ = 0;
  Vec3 x_start_ = Vec3::Zero(), v_start_ = Vec3::Zero(), w_start_ = Vec3::Zero(), x_sum_ = Vec3::Zero();
  double t_start_ = 0.0;
};

}  // namespace silodem
