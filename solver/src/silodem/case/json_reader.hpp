#pragma once
// Strict reading of one JSON object: every read names its JSON path, every value is checked for
// type and finiteness, and finish() rejects keys nobody read (with a "did you mean" hint), so a
// misspelt key can never be silently ignored.
#include <nlohmann/json.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "silodem/case/case_error.hpp"
#include "silodem/core/types.hpp"

namespace silodem {

class JsonReader {
 public:
  JsonReader(const nlohmann::json& j, std::string path);

  const std::string& path() const { return path_; }
  bool has(const std::string& key) const;
  std::string child_path(const std::string& key) const;

  double number(const std::string& key) const;
  std::optional<double> opt_number(const std::string& key) const;
  double number_or(const std::string& key, double fallback) const;
  /// A number in [lo, hi]; the bounds are physical plausibility limits, so a typo such as 1e308
  /// is refused here rather than overflowing in a derived quantity.
  double number_in(const std::string& key, double lo, double hi, const std::string& unit) const;
  double number_in_or(const std::string& key, double lo, double hi, const std::string& unit, double fallback) const;
  long integer(const std::string& key) const;
  long integer_or(const std::string& key, long fallback) const;
  /// An integer in [lo, hi], checked before any narrowing.
  long integer_in_or(const std::string& key, long lo, long hi, long fallback) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  std::string string(const std::string& key) const;
  std::string string_or(const std::string& key, const std::string& fallback) const;
  /// A string that must be one of `choices`.
  std::string choice_or(const std::string& key, const std::vector<std::string>& choices,
                        const std::string& fallback) const;
  Vec3 vec3(const std::string& key) const;
  Vec3 vec3_or(const std::string& key, const Vec3& fallback) const;
  /// A vector whose components are at most `max_abs` in magnitude.
  Vec3 vec3_within(const std::string& key, double max_abs, const std::string& unit) const;
  /// [lo, hi] with lo <= hi.
  std::pair<double, double> range(const std::string& key) const;
  /// [lo, hi] with both ends in [min, max].
  std::pair<double, double> range_in(const std::string& key, double min, double max, const std::string& unit) const;
  JsonReader object(const std::string& key) const;
  std::optional<JsonReader> opt_object(const std::string& key) const;
  const nlohmann::json& array(const std::string& key) const;
  const nlohmann::json& raw(const std::string& key) const;

  /// Throws for keys present but never read.
  void finish() const;

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;

 private:
  const nlohmann::json& get(const std::string& key) const;
  const nlohmann::json* j_;
  std::string path_;
  mutable std::set<std::string> read_;
  mutable std::set<std::string> expected_;  // keys looked up, present or not: hint candidates
};

/// A finite number at `path` (used for array elements).
double json_number(const nlohmann::json& j, const std::string& path);
/// A finite number in [lo, hi] at `path`.
double json_number_in(const nlohmann::json& j, const std::string& path, double lo, double hi, const std::string& unit);
/// A number as the messages print it: shortest round-trip form, so 1e-06 is not shown as 0.000001.
std::string format_number(double v);
/// Edit distance, for "did you mean" hints.
std::size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace silodem
