#pragma once
// Reading result files (summary JSON, probe CSVs). The comparator sees only these files, whatever
// code wrote them.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace harness {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::size_t column(const std::string& name) const;  // throws if absent
  double number(std::size_t row, const std::string& name) const;
  const std::string& text(std::size_t row, const std::string& name) const;
  std::size_t size() const { return rows.size(); }
};

CsvTable read_csv(const std::filesystem::path& file);

struct ResultSet {
  std::filesystem::path dir;
  nlohmann::json summary;
  /// The CSV of a probe named in the summary.
  CsvTable probe(const std::string& name) const;
  const nlohmann::json& probe_digest(const std::string& name) const;
};

/// Reads <dir>/summary.json and refuses a result that is not marked complete.
ResultSet read_result(const std::filesystem::path& dir);

}  // namespace harness
