#include "silodem/scene/drum_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "silodem/scene/even_steps.hpp"

namespace silodem {

namespace {

/// A direction in the x–z plane at angle a from +x (turning towards +z).
Vec3 radial(double a) { return Vec3(std::cos(a), 0.0, std::sin(a)); }

struct Polygon {
  std::vector<Vec3> vertex;  // relative to the centre, vertex k at angle 2πk/N
  double apothem;            // the inscribed radius
};

Polygon polygon(const WallSpec& w) {
  const double R = 0.5 * w.diameter;
  Polygon p{{}, R * std::cos(kPi / w.sides)};
  for (int k = 0; k < w.sides; ++k) p.vertex.push_back(R * radial(2.0 * kPi * k / w.sides));
  return p;
}

/// Points along each face (vertices once), with the face's outward normal.
std::vector<std::pair<Vec3, Vec3>> face_points(const WallSpec& w, double step) {
  const Polygon p = polygon(w);
  std::vector<std::pair<Vec3, Vec3>> out;
  for (int k = 0; k < w.sides; ++k) {
    const Vec3 &a = p.vertex[std::size_t(k)], &b = p.vertex[std::size_t((k + 1) % w.sides)];
    const Vec3 normal = radial(2.0 * kPi * (k + 0.5) / w.sides);
    const std::vector<double> ts = even_steps(0.0, (b - a).norm(), step);
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) out.push_back({a + (b - a).normalized() * ts[i], normal});
  }
  return out;
}

std::vector<double> along_axis(const WallSpec& w, double step) {
  return w.length > 0.0 ? even_steps(-0.5 * w.length, 0.5 * w.length, step) : std::vector<double>{0.0};
}

/// Points of an end plate (the polygon's area on a square grid), relative to the centre.
std::vector<Vec3> plate_points(const WallSpec& w, double step) {
  const Polygon p = polygon(w);
  std::vector<Vec3> out;
  const double R = 0.5 * w.diameter;
  for (const double x : even_steps(-R, R, step))
    for (const double z : even_steps(-R, R, step)) {
      const Vec3 q(x, 0.0, z);
      bool inside = true;
      for (int k = 0; k < w.sides && inside; ++k) inside = q.dot(radial(2.0 * kPi * (k + 0.5) / w.sides)) <= p.apothem;
      if (inside) out.push_back(q);
    }
  return out;
}

}  // namespace

std::vector<BallSpec> build_drum(const WallSpec& w, Random& rng) {
  std::vector<BallSpec> out;
  const double rm = 0.5 * (w.r_min + w.r_max);
  const auto place = [&](const Vec3& centre_of_ball) {
    BallSpec b;
    b.radius = w.r_min + (w.r_max - w.r_min) * rng.uniform();
    b.position = centre_of_ball;
    b.id = w.name + "_" + std::to_string(out.size());
    b.material = w.material;
    b.fixed = true;
    out.push_back(b);
  };
  const Vec3 axis = Vec3::UnitY();
  for (const double y : along_axis(w, w.spacing)) {
    for (const auto& [point, normal] : face_points(w, w.spacing)) place(w.centre + y * axis + point + rm * normal);
    // Lifters: a bar of balls on the radius through each face's middle, from the face inwards.
    const double apothem = polygon(w).apothem;
    for (int k = 0; k < w.lifters; ++k) {
      const Vec3 dir = radial(2.0 * kPi * (double(k) * w.sides / w.lifters + 0.5) / w.sides);
      for (const double h : even_steps(0.0, w.lifter_height, w.spacing)) place(w.centre + y * axis + (apothem - h) * dir);
    }
  }
  if (w.length > 0.0)
    for (const double side : {-1.0, 1.0})
      for (const Vec3& q : plate_points(w, w.spacing)) place(w.centre + (side * (0.5 * w.length + rm)) * axis + q);
  return out;
}

std::vector<Vec3> drum_surface_samples(const WallSpec& w, double step) {
  std::vector<Vec3> out;
  const Vec3 axis = Vec3::UnitY();
  for (const double y : along_axis(w, step))
    for (const auto& fp : face_points(w, step)) out.push_back(w.centre + y * axis + fp.first);
  if (w.length > 0.0)
    for (const double side : {-1.0, 1.0})
      for (const Vec3& q : plate_points(w, step)) out.push_back(w.centre + (side * 0.5 * w.length) * axis + q);
  return out;
}

}  // namespace silodem
