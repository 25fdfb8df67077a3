#include "silodem/output/vtk_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <functional>
#include <string>
#include <vector>

#include "silodem/output/checked_file.hpp"

namespace silodem {

namespace fs = std::filesystem;

namespace {

void write_piece(const fs::path& file, const Particles& p, std::size_t from, std::size_t to) {
  {
    std::ostringstream out;
    const std::size_t n = to - from;
    char b[128];
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           " <PolyData>\n"
        << "  <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
        << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
    const auto vectors = [&](const char* name, const std::vector<Vec3>& v) {
      out << "    <DataArray type=\"Float64\"" << (name[0] ? std::string(" Name=\"") + name + "\"" : std::string())
          << " NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (std::size_t i = from; i < to; ++i) {
        std::snprintf(b, sizeof b, "%.17g %.17g %.17g\n", v[i].x(), v[i].y(), v[i].z());
        out << b;
      }
      out << "    </DataArray>\n";
    };
    const auto scalars = [&](const char* name, const char* type, const std::function<std::string(std::size_t)>& value) {
      out << "    <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
      for (std::size_t i = from; i < to; ++i) out << value(i) << '\n';
      out << "    </DataArray>\n";
    };
    const auto real = [&](double x) {
      std::snprintf(b, sizeof b, "%.17g", x);
      return std::string(b);
    };
    out << "   <Points>\n";
    vectors("", p.x);
    out << "   </Points>\n   <PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
    scalars("radius", "Float64", [&](std::size_t i) { return real(p.r[i]); });
    scalars("mass", "Float64", [&](std::size_t i) { return real(p.m[i]); });
    vectors("velocity", p.v);
    vectors("force", p.f);
    scalars("tag", "Int64", [&](std::size_t i) { return std::to_string(p.tag[i]); });
    out << "   </PointData>\n   <Verts>\n";
    out << "    <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < n; ++k) out << k << '\n';
    out << "    </DataArray>\n    <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t k = 1; k <= n; ++k) out << k << '\n';
    out << "    </DataArray>\n   </Verts>\n  </Piece>\n </PolyData>\n</VTKFile>\n";
    write_file_checked(file, out.str());
  }
}

void write_collection(const fs::path& dir, const std::string& kind, double dt) {
  std::vector<long> steps;
  const std::string prefix = kind + "_";
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && e.path().extension() == ".vtp")
      steps.push_back(std::stol(name.substr(prefix.size(), name.size() - prefix.size() - 4)));
  }
  std::sort(steps.begin(), steps.end());
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
         " <Collection>\n";
  char b[64];
  for (const long s : steps) {
    std::snprintf(b, sizeof b, "%.17g", double(s) * dt);
    out << "  <DataSet timestep=\"" << b << "\" group=\"\" part=\"0\" file=\"" << prefix << s << ".vtp\"/>\n";
  }
  out << " </Collection>\n</VTKFile>\n";
  write_file_checked(dir / (kind + ".pvd"), out.str());
}

}  // namespace

VtkWriter::VtkWriter(fs::path dir, double dt) : dir_(std::move(dir)), dt_(dt) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw WriteError(dir_, "cannot create the directory: " + ec.message());
}

void VtkWriter::frame(long step, const Particles& p) const {
  write_piece(dir_ / ("balls_" + std::to_string(step) + ".vtp"), p, 0, p.n_mobile);
  write_piece(dir_ / ("walls_" + std::to_string(step) + ".vtp"), p, p.n_mobile, p.size());
}

void VtkWriter::finish() const {
  write_collection(dir_, "balls", dt_);
  write_collection(dir_, "walls", dt_);
}

}  // namespace silodem
