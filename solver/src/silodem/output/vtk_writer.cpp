#include "silodem/output/vtk_writer.hpp"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "silodem/output/checked_file.hpp"

namespace silodem {

namespace fs = std::filesystem;

namespace {

/// The arrays of one piece in VTK's appended raw form: each array its byte count (UInt64, the
/// header_type) and its values, little-endian, after the XML that gives each array's offset.
class AppendedArrays {
 public:
  explicit AppendedArrays(bool float64) : float64_(float64) {}
  const char* real_type() const { return float64_ ? "Float64" : "Float32"; }
  /// Appends `n` rows of `components` reals from get(i, c); returns the array's XML element.
  template <class Get>
  std::string reals(const char* name, std::size_t n, int components, Get get) {
    const std::string xml = element(name, real_type(), components);
    begin(n * std::size_t(components) * (float64_ ? 8 : 4));
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < components; ++c) {
        const double x = get(i, c);
        if (float64_) put(x);
        else put(float(std::clamp(x, -double(FLT_MAX), double(FLT_MAX))));  // beyond float: the largest float
      }
    return xml;
  }
  template <class Get>
  std::string int32s(const char* name, std::size_t n, Get get) {
    const std::string xml = element(name, "Int32", 1);
    begin(n * 4);
    for (std::size_t i = 0; i < n; ++i) put(std::int32_t(get(i)));
    return xml;
  }
  const std::string& data() const { return data_; }

 private:
  std::string element(const char* name, const char* type, int components) const {
    return std::string("    <DataArray type=\"") + type + "\"" + (name[0] ? std::string(" Name=\"") + name + "\"" : "") +
           " NumberOfComponents=\"" + std::to_string(components) + "\" format=\"appended\" offset=\"" +
           std::to_string(data_.size()) + "\"/>\n";
  }
  void begin(std::uint64_t bytes) { put(bytes); }
  template <class T>
  void put(const T& v) { data_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  bool float64_;
  std::string data_;
};

void write_piece(const fs::path& file, const Particles& p, std::size_t from, std::size_t to, bool float64) {
  const std::size_t n = to - from;
  AppendedArrays a(float64);
  const auto vec = [&](const std::vector<Vec3>& v) { return [&v, from](std::size_t i, int c) { return v[from + i][c]; }; };
  const auto one = [&](const std::vector<double>& v) { return [&v, from](std::size_t i, int) { return v[from + i]; }; };
  std::string xml = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                    " <PolyData>\n  <Piece NumberOfPoints=\"" + std::to_string(n) +
                    "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n   <Points>\n";
  xml += a.reals("", n, 3, vec(p.x));
  xml += "   </Points>\n   <PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
  xml += a.reals("radius", n, 1, one(p.r));
  xml += a.reals("mass", n, 1, one(p.m));
  xml += a.reals("velocity", n, 3, vec(p.v));
  xml += a.reals("force", n, 3, vec(p.f));
  // Tags stay below 2^31: at most 1e8 balls and 1e9 drops (case/limits.hpp).
  xml += a.int32s("tag", n, [&](std::size_t i) { return p.tag[from + i]; });
  xml += "   </PointData>\n  </Piece>\n </PolyData>\n <AppendedData encoding=\"raw\">\n  _";
  write_file_checked(file, xml + a.data() + "\n </AppendedData>\n</VTKFile>\n");
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

VtkWriter::VtkWriter(fs::path dir, double dt, bool float64) : dir_(std::move(dir)), dt_(dt), float64_(float64) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw WriteError(dir_, "cannot create the directory: " + ec.message());
}

void VtkWriter::frame(long step, const Particles& p) const {
  write_piece(dir_ / ("balls_" + std::to_string(step) + ".vtp"), p, 0, p.n_mobile, float64_);
  write_piece(dir_ / ("walls_" + std::to_string(step) + ".vtp"), p, p.n_mobile, p.size(), float64_);
}

void VtkWriter::finish() const {
  write_collection(dir_, "balls", dt_);
  write_collection(dir_, "walls", dt_);
}

}  // namespace silodem
