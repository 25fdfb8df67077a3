#include "silodem/scene/tray_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "silodem/scene/even_steps.hpp"

namespace silodem {

namespace {

/// The stretches of floor between the slots, as ranges of ball-centre x (relative to the centre).
std::vector<std::pair<double, double>> floor_pieces(const WallSpec& w) {
  const double rm = 0.5 * (w.r_min + w.r_max);
  std::vector<std::pair<double, double>> out;
  double from = -0.5 * w.length;
  for (const auto& slot : w.slots) {
    out.push_back({from, slot.x - 0.5 * slot.width - rm});
    from = slot.x + 0.5 * slot.width + rm;
  }
  out.push_back({from, 0.5 * w.length});
  return out;
}

std::vector<double> depth_rows(const WallSpec& w) {
  return w.depth > 0.0 ? even_steps(-0.5 * w.depth, 0.5 * w.depth, w.spacing) : std::vector<double>{0.0};
}

}  // namespace

std::vector<BallSpec> build_tray(const WallSpec& w, Random& rng) {
  std::vector<BallSpec> out;
  const double rm = 0.5 * (w.r_min + w.r_max);
  const Vec3& c = w.centre;
  const auto place = [&](const Vec3& surface, const Vec3& normal_out) {
    BallSpec b;
    b.radius = w.r_min + (w.r_max - w.r_min) * rng.uniform();
    b.position = surface + rm * normal_out;
    b.id = w.name + "_" + std::to_string(out.size());
    b.material = w.material;
    b.fixed = true;
    out.push_back(b);
  };
  const std::vector<double> ys = depth_rows(w), zs = even_steps(c.z(), c.z() + w.height, w.spacing);
  for (const double y : ys) {
    for (const auto& [a, b] : floor_pieces(w))
      for (const double x : even_steps(a, b, w.spacing)) place(c + Vec3(x, y, 0.0), Vec3(0, 0, -1));
    for (const double side : {-1.0, 1.0})
      for (const double z : zs) place(Vec3(c.x() + side * 0.5 * w.length, c.y() + y, z), Vec3(side, 0, 0));
  }
  if (w.depth > 0.0)
    for (const double side : {-1.0, 1.0})
      for (const double x : even_steps(-0.5 * w.length, 0.5 * w.length, w.spacing))
        for (const double z : zs) place(Vec3(c.x() + x, c.y() + side * 0.5 * w.depth, z), Vec3(0, side, 0));
  return out;
}

std::vector<Vec3> tray_surface_samples(const WallSpec& w, double step) {
  std::vector<Vec3> out;
  const Vec3& c = w.centre;
  const double reach = w.r_max + w.spacing;  // past a slot's edge ball the floor is the ball itself
  const auto in_slot = [&](double x) {
    return std::any_of(w.slots.begin(), w.slots.end(),
                       [&](const auto& s) { return std::abs(x - s.x) < 0.5 * s.width + reach; });
  };
  const std::vector<double> ys = w.depth > 0.0 ? even_steps(-0.5 * w.depth, 0.5 * w.depth, step) : std::vector<double>{0.0};
  const std::vector<double> xs = even_steps(-0.5 * w.length, 0.5 * w.length, step), zs = even_steps(c.z(), c.z() + w.height, step);
  for (const double y : ys) {
    for (const double x : xs)
      if (!in_slot(x)) out.push_back(c + Vec3(x, y, 0.0));
    for (const double side : {-1.0, 1.0})
      for (const double z : zs) out.push_back(Vec3(c.x() + side * 0.5 * w.length, c.y() + y, z));
  }
  if (w.depth > 0.0)
    for (const double side : {-1.0, 1.0})
      for (const double x : xs)
        for (const double z : zs) out.push_back(Vec3(c.x() + x, c.y() + side * 0.5 * w.depth, z));
  return out;
}

}  // namespace silodem
