#include "silodem/output/state_binary.hpp"

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <numeric>
#include <set>

#include "silodem/case/case_error.hpp"
#include "silodem/case/json_reader.hpp"
#include "silodem/output/checked_file.hpp"
#include "silodem/output/state_file.hpp"

namespace silodem {

namespace fs = std::filesystem;
using nlohmann::json;

static_assert(std::endian::native == std::endian::little, "the compact state is written little-endian as it is in memory");

namespace {

/// What the writer needs of a ball, in the order the file lists them.
struct BallSource {
  std::size_t count = 0;
  bool rotating = false;
  std::function<const std::string&(std::size_t)> id;
  std::function<int(std::size_t)> material;
  std::function<bool(std::size_t)> fixed;
  std::function<double(std::size_t)> radius;
  std::function<const Vec3&(std::size_t)> position, velocity, angular_velocity;
};

json column(const char* name, const char* type, int components, const char* unit, std::uint64_t offset,
            std::uint64_t bytes) {
  return {{"name", name}, {"type", type}, {"components", components}, {"unit", unit}, {"offset", offset}, {"bytes", bytes}};
}

/// Streams the columns through a small buffer: a state of 10^6 balls never exists twice in memory.
void write_source(const fs::path& file, const json& meta, const BallSource& s) {
  const std::uint64_t n = s.count;
  std::uint64_t id_bytes = 0;
  for (std::size_t i = 0; i < n; ++i) id_bytes += s.id(i).size() + 1;
  json cols = json::array();
  std::uint64_t at = 0;
  const auto add = [&](const char* name, const char* type, int comps, const char* unit, std::uint64_t bytes) {
    cols.push_back(column(name, type, comps, unit, at, bytes));
    at += bytes;
  };
  add("id", "str", 1, "", id_bytes);
  add("material", "u16", 1, "", 2 * n);
  add("fixed", "u8", 1, "", n);
  add("radius", "f64", 1, "m", 8 * n);
  add("position", "f64", 3, "m", 24 * n);
  add("velocity", "f64", 3, "m/s", 24 * n);
  if (s.rotating) add("angular_velocity", "f64", 3, "rad/s", 24 * n);
  json header = meta;
  header["count"] = n;
  header["byte_order"] = "little";
  header["columns"] = std::move(cols);
  header["data_bytes"] = at;

  write_file_atomically(file, [&](CheckedFile& out) {
    // "format" first, whatever the JSON library's key order: the file is recognised by its first bytes.
    header.erase("format");
    out.write(std::string("{\"format\":\"") + kStateBinaryFormat + "\"," + header.dump().substr(1) + "\n");
    std::string buf;
    const auto put = [&](const void* data, std::size_t bytes) {
      buf.append(static_cast<const char*>(data), bytes);
      if (buf.size() > (1u << 20)) out.write(buf), buf.clear();
    };
    for (std::size_t i = 0; i < n; ++i) put(s.id(i).c_str(), s.id(i).size() + 1);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint16_t m = std::uint16_t(s.material(i));
      put(&m, 2);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint8_t f = s.fixed(i) ? 1 : 0;
      put(&f, 1);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double r = s.radius(i);
      put(&r, 8);
    }
    const auto vectors = [&](const std::function<const Vec3&(std::size_t)>& v) {
      for (std::size_t i = 0; i < n; ++i) put(v(i).data(), 24);
    };
    vectors(s.position);
    vectors(s.velocity);
    if (s.rotating) vectors(s.angular_velocity);
    out.write(buf);
  });
}

json meta(const std::string& case_name, double dt, long step, double t, const std::vector<std::string>& materials) {
  return {{"format", kStateBinaryFormat}, {"case", case_name}, {"step", step}, {"time", t}, {"dt", dt},
          {"materials", materials}};
}

}  // namespace

bool is_binary_state(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string head(40, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  return head.rfind(std::string("{\"format\":\"") + kStateBinaryFormat + "\"", 0) == 0;
}

void write_state_binary(const fs::path& file, const std::string& case_name, double dt, const Particles& p,
                        const std::vector<std::string>& material_names, long step, double t) {
  if (!state_is_finite(p)) throw std::logic_error("a non-finite state reached " + file.string());
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.tag[a] < p.tag[b]; });
  static const Vec3 zero = Vec3::Zero();
  BallSource s;
  s.count = p.size();
  s.rotating = p.rotating;
  s.id = [&](std::size_t k) -> const std::string& { return p.id[order[k]]; };
  s.material = [&](std::size_t k) { return int(p.material[order[k]]); };
  s.fixed = [&](std::size_t k) { return p.fixed(order[k]); };
  s.radius = [&](std::size_t k) { return p.r[order[k]]; };
  s.position = [&](std::size_t k) -> const Vec3& { return p.x[order[k]]; };
  s.velocity = [&](std::size_t k) -> const Vec3& { return p.fixed(order[k]) ? zero : p.v[order[k]]; };
  s.angular_velocity = [&](std::size_t k) -> const Vec3& { return p.fixed(order[k]) ? zero : p.w[order[k]]; };
  write_source(file, meta(case_name, dt, step, t, material_names), s);
}

namespace {

struct Column {
  const char* data = nullptr;
  std::uint64_t bytes = 0;
};

/// The columns' places in `data`, each checked against the count before a byte of it is used.
class ColumnTable {
 public:
  ColumnTable(const json& header, const std::vector<char>& data, std::size_t n, const std::string& where)
      : data_(data), n_(n), where_(where) {
    if (!header.contains("columns") || !header["columns"].is_array()) throw CaseError(where, "the header has no column list");
    columns_ = &header["columns"];
    std::set<std::string> names;
    for (const auto& c : *columns_) {
      if (!c.is_object() || !c.contains("name") || !c["name"].is_string()) throw CaseError(where, "a column without a name");
      if (!names.insert(c["name"].get<std::string>()).second)
        throw CaseError(where, "column \"" + c["name"].get<std::string>() + "\" is listed twice");
    }
  }

  Column find(const std::string& name, const std::string& type, int comps, bool required) const {
    for (const auto& c : *columns_) {
      if (c["name"] != name) continue;
      const JsonReader cr(c, where_ + " column " + name);
      const long off = cr.integer("offset"), bytes = cr.integer("bytes");
      if (cr.string("type") != type || cr.integer("components") != comps)
        cr.fail("type", "expected " + type + " with " + std::to_string(comps) + " components");
      const std::uint64_t elem = type == "f64" ? 8 : type == "u16" ? 2 : 1;
      const std::uint64_t size = data_.size();
      if (off < 0 || bytes < 0 || std::uint64_t(off) > size || std::uint64_t(bytes) > size - std::uint64_t(off))
        cr.fail("offset", "lies outside the data");
      if (type != "str" && std::uint64_t(bytes) != elem * std::uint64_t(comps) * n_) cr.fail("bytes", "does not match count");
      return {data_.data() + off, std::uint64_t(bytes)};
    }
    if (required) throw CaseError(where_, "no column \"" + name + "\"");
    return {};
  }

 private:
  const std::vector<char>& data_;
  std::size_t n_;
  std::string where_;
  const json* columns_ = nullptr;
};

StateSnapshot read_columns(const json& h, std::ifstream& in, const fs::path& file, const std::string& where) {
  const JsonReader r(h, where + " header $");
  if (r.string("format") != kStateBinaryFormat) r.fail("format", std::string("expected \"") + kStateBinaryFormat + "\"");
  if (r.string("byte_order") != "little") r.fail("byte_order", "expected \"little\"");
  StateSnapshot s = read_state_header(r);
  const long count = r.integer("count");
  if (count < 0 || count > 100'000'000) r.fail("count", "must be in [0, 1e8]");
  const std::size_t n = std::size_t(count);
  const std::vector<std::string> materials = r.raw("materials").get<std::vector<std::string>>();
  const long data_bytes = r.integer("data_bytes");
  const std::streamoff data_start = in.tellg();
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec || data_start < 0 || data_bytes < 0 || size != std::uintmax_t(data_start) + std::uintmax_t(data_bytes))
    throw CaseError(where, "the file has " + std::to_string(size) + " bytes; its header promises " +
                               std::to_string(data_start + data_bytes) + " (truncated or appended to)");
  std::vector<char> data(static_cast<std::size_t>(data_bytes));
  in.read(data.data(), std::streamsize(data_bytes));
  if (!in) throw CaseError(where, "cannot read the columns");

  const ColumnTable table(h, data, n, where);
  const Column ids = table.find("id", "str", 1, true);
  const char* id = ids.data;
  const char* ids_end = ids.data + ids.bytes;
  const char* mat = table.find("material", "u16", 1, true).data;
  const char* fixed = table.find("fixed", "u8", 1, true).data;
  const char* radius = table.find("radius", "f64", 1, true).data;
  const char* pos = table.find("position", "f64", 3, true).data;
  const char* vel = table.find("velocity", "f64", 3, true).data;
  const char* spin = table.find("angular_velocity", "f64", 3, false).data;
  const auto vec = [](const char* col, std::size_t i) {
    Vec3 v;
    std::memcpy(v.data(), col + 24 * i, 24);
    return v;
  };
  s.balls.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    BallSpec& b = s.balls[i];
    const char* end = static_cast<const char*>(std::memchr(id, '\0', std::size_t(ids_end - id)));
    if (!end) throw CaseError(where, "the id column ends before ball " + std::to_string(i));
    b.id.assign(id, end);
    id = end + 1;
    std::uint16_t m;
    std::memcpy(&m, mat + 2 * i, 2);
    if (m >= materials.size()) throw CaseError(where, "ball \"" + b.id + "\": material index " + std::to_string(m) + " is not listed");
    b.material = materials[m];
    b.fixed = fixed[i] != 0;
    std::memcpy(&b.radius, radius + 8 * i, 8);
    b.position = vec(pos, i);
    b.velocity = vec(vel, i);
    if (spin) b.angular_velocity = vec(spin, i);
    if (!(b.radius > 0.0) || !std::isfinite(b.radius) || !b.position.allFinite() || !b.velocity.allFinite() ||
        !b.angular_velocity.allFinite())
      throw CaseError(where, "ball \"" + b.id + "\": a radius that is not positive or a value that is not finite");
  }
  if (id != ids_end) throw CaseError(where, "the id column holds more ids than count");
  return s;
}

}  // namespace

StateSnapshot read_state_binary(const fs::path& file) {
  const std::string where = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CaseError(where, "cannot read the state file");
  std::string line;
  if (!std::getline(in, line) || line.size() > (1u << 20)) throw CaseError(where, "no header line");
  try {
    return read_columns(json::parse(line), in, file, where);
  } catch (const json::exception& e) {
    // A header field of the wrong JSON type: bad input like any other, named as such.
    throw CaseError(where, std::string("the header line is malformed: ") + e.what());
  }
}

}  // namespace silodem
