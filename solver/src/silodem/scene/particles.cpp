#include "silodem/scene/particles.hpp"

#include "silodem/checkpoint/archive.hpp"

#include <stdexcept>

namespace silodem {

void Particles::push(const Ball& b) {
  x.push_back(b.x);
  v.push_back(b.v);
  f.push_back(Vec3::Zero());
  r.push_back(b.r);
  m.push_back(b.m);
  k.push_back(b.k);
  c.push_back(b.c);
  material.push_back(b.material);
  id.push_back(b.id);
  tag.push_back(b.tag);
  if (rotating) w.push_back(b.w), t.push_back(Vec3::Zero());
}

void Particles::keep_in_plane() {
  for (std::size_t i = 0; i < n_mobile; ++i) f[i].y() = 0.0;
  if (rotating)
    for (std::size_t i = 0; i < n_mobile; ++i) t[i].x() = t[i].z() = 0.0;
}

void Particles::enable_rotation() {
  rotating = true;
  w.resize(size(), Vec3::Zero());
  t.resize(size(), Vec3::Zero());
}

void Particles::refresh_moving_walls() {
  moving_walls = driven_walls;
  for (std::size_t i = n_mobile; i < size() && !moving_walls; ++i) moving_walls = !v[i].isZero();
}

void Particles::move(std::size_t from, std::size_t to) {
  x[to] = x[from];
  v[to] = v[from];
  f[to] = f[from];
  r[to] = r[from];
  m[to] = m[from];
  k[to] = k[from];
  c[to] = c[from];
  material[to] = material[from];
  id[to] = std::move(id[from]);
  tag[to] = tag[from];
  if (rotating) w[to] = w[from], t[to] = t[from];
}

void Particles::reserve(std::size_t n) {
  x.reserve(n);
  v.reserve(n);
  f.reserve(n);
  r.reserve(n);
  m.reserve(n);
  k.reserve(n);
  c.reserve(n);
  material.reserve(n);
  id.reserve(n);
  tag.reserve(n);
  if (rotating) w.reserve(n), t.reserve(n);
}

std::size_t Particles::add(const Ball& b, bool is_fixed) {
  ++topology;
  push(b);
  if (is_fixed) return size() - 1;
  // Keep the mobile range contiguous: the first wall ball moves to the new last slot.
  const std::size_t slot = n_mobile++;
  if (slot != size() - 1) {
    move(slot, size() - 1);
    x[slot] = b.x;
    v[slot] = b.v;
    f[slot] = Vec3::Zero();
    r[slot] = b.r;
    m[slot] = b.m;
    k[slot] = b.k;
    c[slot] = b.c;
    material[slot] = b.material;
    id[slot] = b.id;
    tag[slot] = b.tag;
    if (rotating) w[slot] = b.w, t[slot] = Vec3::Zero();
  }
  return slot;
}

void Particles::swap_slots(std::size_t a, std::size_t b) {
  if (a == b) return;
  std::swap(x[a], x[b]);
  std::swap(v[a], v[b]);
  std::swap(f[a], f[b]);
  std::swap(r[a], r[b]);
  std::swap(m[a], m[b]);
  std::swap(k[a], k[b]);
  std::swap(c[a], c[b]);
  std::swap(material[a], material[b]);
  std::swap(id[a], id[b]);
  std::swap(tag[a], tag[b]);
  if (rotating) std::swap(w[a], w[b]), std::swap(t[a], t[b]);
}

Particles::Ball Particles::ball(std::size_t i) const {
  return {x[i], v[i], r[i], m[i], k[i], c[i], material[i], id[i], tag[i], rotating ? w[i] : Vec3::Zero()};
}

std::size_t Particles::make_mobile(std::size_t i) {
  ++topology;
  swap_slots(i, n_mobile);
  return n_mobile++;
}

std::size_t Particles::make_fixed(std::size_t i) {
  ++topology;
  swap_slots(i, --n_mobile);
  v[n_mobile].setZero();
  if (rotating) w[n_mobile].setZero();
  return n_mobile;
}

void Particles::remove_mobile(std::size_t i) {
  ++topology;
  swap_slots(i, --n_mobile);               // to the end of the mobile range
  swap_slots(n_mobile, size() - 1);        // the last wall ball takes its slot
  x.pop_back();
  v.pop_back();
  f.pop_back();
  r.pop_back();
  m.pop_back();
  k.pop_back();
  c.pop_back();
  material.pop_back();
  id.pop_back();
  tag.pop_back();
  if (rotating) w.pop_back(), t.pop_back();
}

void Particles::permute_mobile(const std::vector<std::uint32_t>& order) {
  if (order.size() != n_mobile) throw std::invalid_argument("permute_mobile: the order is not one of the mobile balls");
  ++topology;
  permute_front(x, order);
  permute_front(v, order);
  permute_front(f, order);
  permute_front(r, order);
  permute_front(m, order);
  permute_front(k, order);
  permute_front(c, order);
  permute_front(material, order);
  permute_front(id, order);
  permute_front(tag, order);
  if (rotating) permute_front(w, order), permute_front(t, order);
}

std::ptrdiff_t Particles::find(const std::string& ball_id) const {
  for (std::size_t i = 0; i < id.size(); ++i)
    if (id[i] == ball_id) return std::ptrdiff_t(i);
  return -1;
}

std::size_t Particles::bytes() const {
  std::size_t b = heap_bytes(x) + heap_bytes(v) + heap_bytes(f) + heap_bytes(r) + heap_bytes(m) + heap_bytes(k) +
                  heap_bytes(c) + heap_bytes(material) + heap_bytes(id) + heap_bytes(tag) + heap_bytes(w) +
                  heap_bytes(t);
  for (const auto& s : id)
    if (s.capacity() > 15) b += s.capacity() + 1;  // beyond the small-string buffer
  return b;
}

// The rotation arrays are written only by a rotating scene, whose case makes the reader's
// particles rotating too: a frictionless checkpoint keeps its layout.
void Particles::Ball::serialize(Archive& a) { a & x & v & r & m & k & c & material & id & tag; }

void Particles::serialize(Archive& a) {
  a & x & v & f & r & m & k & c & material & id & tag & n_mobile & topology;
  if (rotating) a & w & t;
  if (a.loading()) {
    if (rotating && (w.size() != x.size() || t.size() != x.size()))
      throw CheckpointError("checkpoint payload is damaged (rotation arrays of another length)");
    for (std::size_t i = 0; rotating && i < w.size(); ++i)
      if (!w[i].allFinite() || !t[i].allFinite())
        throw CheckpointError("checkpoint payload is damaged (ball " + std::to_string(i) + " spins at no finite rate)");
    const std::size_t n = x.size();
    for (std::size_t s : {v.size(), f.size(), r.size(), m.size(), k.size(), c.size(), material.size(), id.size(), tag.size()})
      if (s != n) throw CheckpointError("checkpoint payload is damaged (ball arrays of different lengths)");
    if (n_mobile > n) throw CheckpointError("checkpoint payload is damaged (more mobile balls than balls)");
    // A checkpoint is written only from a state that passed the run guards.
    for (std::size_t i = 0; i < n; ++i)
      if (!x[i].allFinite() || !v[i].allFinite() || !f[i].allFinite() || !(r[i] > 0.0 && r[i] < 1e3) ||
          !(m[i] > 0.0 && m[i] < 1e30) || !(k[i] >= 0.0 && k[i] < 1e30) || !(c[i] >= 0.0 && c[i] < 1e30))
        throw CheckpointError("checkpoint payload is damaged (ball " + std::to_string(i) + " is not a ball)");
    refresh_moving_walls();
  }
}

}  // namespace silodem
