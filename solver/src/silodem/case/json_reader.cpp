#include "silodem/case/json_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace silodem {

using nlohmann::json;

namespace {
std::string type_name(const json& j) {
  if (j.is_number()) return "number";
  if (j.is_boolean()) return "boolean";
  if (j.is_string()) return "string";
  if (j.is_array()) return "array";
  if (j.is_object()) return "object";
  return "null";
}
}  // namespace

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  for (int precision = 1; precision < 17; ++precision) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", precision, v);
    if (std::strtod(shorter, nullptr) == v) return shorter;
  }
  return buf;
}

double json_number(const json& j, const std::string& path) {
  if (j.is_string()) {
    // JSON has no NaN or infinity; writers that emit them as strings would otherwise only get a
    // type error that hides the real problem.
    std::string s = j.get<std::string>();
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.erase(0, 1);
    if (s == "nan" || s == "inf" || s == "infinity")
      throw CaseError(path, "expected a finite number, found the string \"" + j.get<std::string>() + "\"");
  }
  if (!j.is_number()) throw CaseError(path, "expected a number, found " + type_name(j));
  const double v = j.get<double>();
  // The parser turns a literal beyond the double range (1e400) into infinity.
  if (!std::isfinite(v)) throw CaseError(path, "must be a finite number (out of the double range)");
  return v;
}

double json_number_in(const json& j, const std::string& path, double lo, double hi, const std::string& unit) {
  const double v = json_number(j, path);
  if (!(v >= lo && v <= hi))
    throw CaseError(path, "out of range: " + format_number(v) + " is not in [" + format_number(lo) + ", " +
                              format_number(hi) + "]" + (unit.empty() ? "" : " " + unit));
  return v;
}

JsonReader::JsonReader(const json& j, std::string path) : j_(&j), path_(std::move(path)) {
  if (!j.is_object()) throw CaseError(path_, "expected an object, found " + type_name(j));
}

bool JsonReader::has(const std::string& key) const {
  expected_.insert(key);
  return j_->contains(key);
}

std::string JsonReader::child_path(const std::string& key) const { return path_ + "." + key; }

void JsonReader::fail(const std::string& key, const std::string& reason) const {
  throw CaseError(key.empty() ? path_ : child_path(key), reason);
}

const json& JsonReader::get(const std::string& key) const {
  expected_.insert(key);
  auto it = j_->find(key);
  if (it == j_->end()) fail(key, "required value is missing");
  read_.insert(key);
  return *it;
}

double JsonReader::number(const std::string& key) const { return json_number(get(key), child_path(key)); }

std::optional<double> JsonReader::opt_number(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return number(key);
}

double JsonReader::number_or(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

double JsonReader::number_in(const std::string& key, double lo, double hi, const std::string& unit) const {
  return json_number_in(get(key), child_path(key), lo, hi, unit);
}

double JsonReader::number_in_or(const std::string& key, double lo, double hi, const std::string& unit,
                                double fallback) const {
  return has(key) ? number_in(key, lo, hi, unit) : fallback;
}

long JsonReader::integer(const std::string& key) const {
  const json& v = get(key);
  if (!v.is_number_integer()) fail(key, "expected an integer, found " + type_name(v));
  // An unsigned literal beyond the long range would wrap to a negative value.
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<long>::max()))
    fail(key, "out of range: " + v.dump() + " is too large");
  return v.get<long>();
}

long JsonReader::integer_in_or(const std::string& key, long lo, long hi, long fallback) const {
  const long v = integer_or(key, fallback);
  if (v < lo || v > hi)
    fail(key, "out of range: " + std::to_string(v) + " is not in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

long JsonReader::integer_or(const std::string& key, long fallback) const {
  return has(key) ? integer(key) : fallback;
}

bool JsonReader::boolean_or(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const json& v = get(key);
  if (!v.is_boolean()) fail(key, "expected true or false, found " + type_name(v));
  return v.get<bool>();
}

std::string JsonReader::string(const std::string& key) const {
  const json& v = get(key);
  if (!v.is_string()) fail(key, "expected a string, found " + type_name(v));
  return v.get<std::string>();
}

std::string JsonReader::string_or(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

std::string JsonReader::choice_or(const std::string& key, const std::vector<std::string>& choices,
                                  const std::string& fallback) const {
  const std::string v = string_or(key, fallback);
  if (std::find(choices.begin(), choices.end(), v) == choices.end()) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    fail(key, "unknown value \"" + v + "\"; expected one of: " + list);
  }
  return v;
}

Vec3 JsonReader::vec3(const std::string& key) const {
  const json& v = get(key);
  if (!v.is_array() || v.size() != 3) fail(key, "expected an array of 3 numbers [x, y, z]");
  Vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = json_number(v[i], child_path(key) + "[" + std::to_string(i) + "]");
  return out;
}

Vec3 JsonReader::vec3_or(const std::string& key, const Vec3& fallback) const {
  return has(key) ? vec3(key) : fallback;
}

Vec3 JsonReader::vec3_within(const std::string& key, double max_abs, const std::string& unit) const {
  const json& v = get(key);
  if (!v.is_array() || v.size() != 3) fail(key, "expected an array of 3 numbers [x, y, z]");
  Vec3 out;
  for (int i = 0; i < 3; ++i)
    out[i] = json_number_in(v[i], child_path(key) + "[" + std::to_string(i) + "]", -max_abs, max_abs, unit);
  return out;
}

std::pair<double, double> JsonReader::range(const std::string& key) const {
  const json& v = get(key);
  if (!v.is_array() || v.size() != 2) fail(key, "expected an array of 2 numbers [min, max]");
  const double lo = json_number(v[0], child_path(key) + "[0]");
  const double hi = json_number(v[1], child_path(key) + "[1]");
  if (lo > hi) fail(key, "min (" + format_number(lo) + ") is larger than max (" + format_number(hi) + ")");
  return {lo, hi};
}

std::pair<double, double> JsonReader::range_in(const std::string& key, double min, double max,
                                               const std::string& unit) const {
  const auto [lo, hi] = range(key);
  json_number_in(lo, child_path(key) + "[0]", min, max, unit);
  json_number_in(hi, child_path(key) + "[1]", min, max, unit);
  return {lo, hi};
}

JsonReader JsonReader::object(const std::string& key) const { return JsonReader(get(key), child_path(key)); }

std::optional<JsonReader> JsonReader::opt_object(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return object(key);
}

const json& JsonReader::array(const std::string& key) const {
  const json& v = get(key);
  if (!v.is_array()) fail(key, "expected an array, found " + type_name(v));
  return v;
}

const json& JsonReader::raw(const std::string& key) const { return get(key); }

void JsonReader::finish() const {
  for (auto it = j_->begin(); it != j_->end(); ++it) {
    if (read_.count(it.key())) continue;
    std::string hint;
    std::size_t best = 3;
    // Suggest the closest key this reader knows about (those it read, plus the ones it looked for).
    for (const auto& known : read_) {
      const std::size_t d = edit_distance(it.key(), known);
      if (d < best) best = d, hint = known;
    }
    for (const auto& known : expected_) {
      const std::size_t d = edit_distance(it.key(), known);
      if (d < best) best = d, hint = known;
    }
    fail(it.key(), "unknown key" + (hint.empty() ? std::string() : "; did you mean \"" + hint + "\"?"));
  }
}

}  // namespace silodem
