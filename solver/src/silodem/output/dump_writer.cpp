#include "silodem/output/dump_writer.hpp"

#include "silodem/checkpoint/checkpoint_file.hpp"

#include <cstdio>
#include <string>

namespace silodem {

DumpWriter::DumpWriter(const std::filesystem::path& file) : out_(file) {}

namespace {
const std::filesystem::path& resumed(const std::filesystem::path& file, std::uintmax_t bytes) {
  resume_file(file, bytes);
  return file;
}
}  // namespace

DumpWriter::DumpWriter(const std::filesystem::path& file, std::uintmax_t bytes) : out_(resumed(file, bytes), true) {}

std::uintmax_t DumpWriter::flushed_bytes() { return out_.flush(); }

void DumpWriter::frame(long step, const Particles& p) {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  if (p.size() > 0) lo = hi = p.x[0];
  for (std::size_t i = 0; i < p.size(); ++i) lo = lo.cwiseMin(p.x[i]), hi = hi.cwiseMax(p.x[i]);
  std::string text = "ITEM: TIMESTEP\n" + std::to_string(step) + "\nITEM: NUMBER OF ATOMS\n" + std::to_string(p.size()) +
                     "\nITEM: BOX BOUNDS mm mm mm\n";
  char line[512];
  for (int d = 0; d < 3; ++d) {
    std::snprintf(line, sizeof line, "%.17g %.17g\n", lo[d], hi[d]);
    text += line;
  }
  // Angular velocity only where balls rotate (the reference codes' dumps do the same).
  text += p.rotating ? "ITEM: ATOMS id mass radius x y z vx vy vz fx fy fz fixed omegax omegay omegaz\n"
                     : "ITEM: ATOMS id mass radius x y z vx vy vz fx fy fz fixed\n";
  for (std::size_t i = 0; i < p.size(); ++i) {
    int n = std::snprintf(line, sizeof line, "%lld %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d",
                          static_cast<long long>(p.tag[i]), p.m[i], p.r[i], p.x[i].x(), p.x[i].y(), p.x[i].z(), p.v[i].x(),
                          p.v[i].y(), p.v[i].z(), p.f[i].x(), p.f[i].y(), p.f[i].z(), p.fixed(i) ? 1 : 0);
    if (p.rotating)
      n += std::snprintf(line + n, sizeof line - std::size_t(n), " %.17g %.17g %.17g", p.w[i].x(), p.w[i].y(), p.w[i].z());
    text.append(line, std::size_t(n));
    text += '\n';
    if (text.size() > (1u << 20)) out_.write(text), text.clear();
  }
  out_.write(text);
}

}  // namespace silodem
