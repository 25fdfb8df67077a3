#include "harness/trace/dump_reader.hpp"

#include <map>
#include <sstream>
#include <stdexcept>

namespace harness {

DumpReader::DumpReader(const std::filesystem::path& file) : in_(file), file_(file) {
  if (!in_) throw std::runtime_error("cannot read dump " + file.string());
}

bool DumpReader::getline(std::string& s) {
  if (!std::getline(in_, s)) return false;
  ++line_;
  return true;
}

bool DumpReader::next(DumpFrame& frame) {
  std::string s;
  const auto fail = [&](const std::string& why) {
    throw std::runtime_error(file_.string() + ":" + std::to_string(line_) + ": " + why);
  };
  do {
    if (!getline(s)) return false;
  } while (s.empty());
  if (s.rfind("ITEM: TIMESTEP", 0) != 0) fail("expected ITEM: TIMESTEP");
  if (!getline(s)) fail("truncated frame");
  frame.step = std::stol(s);
  if (!getline(s) || s.rfind("ITEM: NUMBER OF ATOMS", 0) != 0) fail("expected ITEM: NUMBER OF ATOMS");
  if (!getline(s)) fail("truncated frame");
  const long n = std::stol(s);
  if (!getline(s) || s.rfind("ITEM: BOX BOUNDS", 0) != 0) fail("expected ITEM: BOX BOUNDS");
  for (int d = 0; d < 3; ++d)
    if (!getline(s)) fail("truncated box bounds");
  if (!getline(s) || s.rfind("ITEM: ATOMS", 0) != 0) fail("expected ITEM: ATOMS");
  std::map<std::string, int> col;
  {
    std::istringstream h(s.substr(11));
    std::string name;
    for (int i = 0; h >> name; ++i) col[name] = i;
  }
  for (const char* need : {"id", "mass", "radius", "x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz"})
    if (!col.count(need)) fail(std::string("dump lacks column ") + need);
  // LAMMPS names an atom-style variable's column v_<name>.
  const int fixed_col = col.count("fixed") ? col["fixed"] : col.count("v_fixed") ? col["v_fixed"] : -1;
  const bool spins = col.count("omegax") && col.count("omegay") && col.count("omegaz");
  if (!spins && (col.count("omegax") || col.count("omegay") || col.count("omegaz"))) fail("dump has only some of omegax, omegay, omegaz");
  frame.atoms.resize(std::size_t(n));
  std::vector<double> v(col.size());
  for (long a = 0; a < n; ++a) {
    if (!getline(s)) fail("truncated atom list");
    std::istringstream row(s);
    for (auto& x : v)
      if (!(row >> x)) fail("short atom row");
    DumpAtom& at = frame.atoms[std::size_t(a)];
    at.id = std::int64_t(v[std::size_t(col["id"])]);
    at.mass = v[std::size_t(col["mass"])];
    at.radius = v[std::size_t(col["radius"])];
    at.x = {v[std::size_t(col["x"])], v[std::size_t(col["y"])], v[std::size_t(col["z"])]};
    at.v = {v[std::size_t(col["vx"])], v[std::size_t(col["vy"])], v[std::size_t(col["vz"])]};
    at.f = {v[std::size_t(col["fx"])], v[std::size_t(col["fy"])], v[std::size_t(col["fz"])]};
    at.has_w = spins;
    if (spins) at.w = {v[std::size_t(col["omegax"])], v[std::size_t(col["omegay"])], v[std::size_t(col["omegaz"])]};
    at.fixed = fixed_col < 0 ? -1 : (v[std::size_t(fixed_col)] != 0.0 ? 1 : 0);
  }
  return true;
}

}  // namespace harness
