#pragma once
// All balls of a scene, structure-of-arrays. Mobile balls occupy [0, n_mobile), wall (fixed) balls
// [n_mobile, size()): integrators loop over the first range only, the force loop over both, and a
// wall ball is simply a ball that is never integrated (STYLE.md: one contact path for all pairs).
#include <cstdint>
#include <string>
#include <vector>

#include "silodem/core/types.hpp"

namespace silodem {

class Archive;

/// a[k] becomes the old a[order[k]] for k < order.size() (a permutation of the front of a): how
/// every per-ball array follows Particles::permute_mobile.
template <class T>
void permute_front(std::vector<T>& a, const std::vector<std::uint32_t>& order) {
  std::vector<T> moved;
  moved.reserve(order.size());
  for (const std::uint32_t from : order) moved.push_back(std::move(a[from]));
  std::move(moved.begin(), moved.end(), a.begin());
}

struct Particles {
  std::vector<Vec3> x;      // position u_i, m
  std::vector<Vec3> v;      // velocity u̇_i, m/s
  std::vector<Vec3> f;      // contact force Σ_j f_ij n_ij (3), N — on wall balls: the wall load
  std::vector<double> r;    // radius, m
  std::vector<double> m;    // mass, kg
  std::vector<double> k;    // per-ball stiffness k_i, N/m
  std::vector<double> c;    // per-ball viscosity c_i, N s/m
  std::vector<std::int32_t> material;  // index into the scene's material names
  std::vector<std::string> id;         // user id, or drop<n> for the n-th drop attempt; probes look balls up by it
  std::vector<std::int64_t> tag;       // 1-based number in case order (drops after the listed balls), as in dumps
  // Rotation (docs/model.md §10.1), only in scenes with a tangential or rolling law: empty otherwise,
  // so that a frictionless scene carries and moves nothing for it.
  std::vector<Vec3> w;      // angular velocity ω_i, rad/s
  std::vector<Vec3> t;      // contact torque about the centre, N m — on wall balls: the wall's
  bool rotating = false;
  bool planar = false;          // grains move in the x–z plane and spin about y (docs/model.md §13)
  double inertia_factor = 0.4;  // κ = I/(m r²): 2/5 a solid sphere, 1/2 a disc
  bool moving_walls = false;  // some wall ball has a velocity (a move_wall event) or a law: walls move and do work
  bool driven_walls = false;  // some wall follows a motion law (motion/wall_motion.hpp): walls keep moving
  std::size_t n_mobile = 0;
  std::uint64_t topology = 0;  // bumped whenever indices change: caches of indices must refresh

  std::size_t size() const { return x.size(); }
  bool fixed(std::size_t i) const { return i >= n_mobile; }
  /// Moment of inertia of a solid sphere, 2/5 m r².
  double inertia(std::size_t i) const { return inertia_factor * m[i] * r[i] * r[i]; }
  /// The planar mode (case "dimension": 2): drops the parts of the mobile balls' forces along y and
  /// of their torques about x and z, so that centres stay in y = 0 and spins along y, bit for bit.
  void keep_in_plane();
  /// Gives every ball an angular velocity (zero) and a torque from now on.
  void enable_rotation();
  /// Sets moving_walls from the wall balls' velocities and driven_walls (after a move_wall event or a restore).
  void refresh_moving_walls();

  struct Ball {
    Vec3 x, v;
    double r, m, k, c;
    std::int32_t material;
    std::string id;
    std::int64_t tag = 0;
    Vec3 w = Vec3::Zero();  // angular velocity (kept only in a rotating scene)
    void serialize(Archive& a);
  };
  /// Appends a mobile ball (before the wall balls) or a wall ball (at the end). Returns its index.
  /// Inserting a mobile ball moves the first wall ball to the end: indices of wall balls change.
  std::size_t add(const Ball& b, bool is_fixed);
  /// No balls, of this set's kind (rotating, planar, inertia factor): a set rebuilt ball by ball.
  Particles empty_like() const {
    Particles q;
    q.rotating = rotating, q.planar = planar, q.inertia_factor = inertia_factor;
    return q;
  }
  /// Room for n balls in every array: a scene that knows its count allocates once, not by
  /// doubling (up to 2× the bytes held at 10^6 balls).
  void reserve(std::size_t n);
  /// Index of the ball with this id, or -1.
  std::ptrdiff_t find(const std::string& ball_id) const;

  // Stage changes of docs/model.md §7. Each keeps the mobile range contiguous by swapping,
  // so indices change (topology is bumped); ids and tags travel with their balls.
  /// A wall ball starts moving (the outlet balls at discharge). Returns its new index.
  std::size_t make_mobile(std::size_t i);
  /// A mobile ball is stopped and becomes a wall ball (sudden gate closure). Returns its new index.
  std::size_t make_fixed(std::size_t i);
  /// A mobile ball leaves the system (discharged through the outlet).
  void remove_mobile(std::size_t i);
  /// Renumbers the mobile balls: ball k becomes the old ball order[k] (a permutation of
  /// [0, n_mobile)). Wall balls keep their indices; the topology is bumped.
  void permute_mobile(const std::vector<std::uint32_t>& order);
  Ball ball(std::size_t i) const;
  /// Heap bytes of all arrays (ids included).
  std::size_t bytes() const;
  /// Checkpoint (checkpoint/archive.hpp): every array, bit for bit; reading checks the sizes agree.
  void serialize(Archive& a);

 private:
  void push(const Ball& b);
  void move(std::size_t from, std::size_t to);
  void swap_slots(std::size_t a, std::size_t b);
};

}  // namespace silodem
