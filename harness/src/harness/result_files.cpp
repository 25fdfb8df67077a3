#include "harness/result_files.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "silodem/output/manifest.hpp"

namespace harness {

namespace fs = std::filesystem;

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  throw std::runtime_error("CSV has no column \"" + name + "\"");
}

double CsvTable::number(std::size_t row, const std::string& name) const {
  const std::string& cell = rows.at(row).at(column(name));
  // Result files write an empty cell where a value does not exist (never nan or inf).
  if (cell.empty()) throw std::runtime_error("CSV column \"" + name + "\" has no value in row " + std::to_string(row));
  return std::stod(cell);
}

const std::string& CsvTable::text(std::size_t row, const std::string& name) const {
  return rows.at(row).at(column(name));
}

CsvTable read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  CsvTable t;
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    if (first) t.header = std::move(cells), first = false;
    else t.rows.push_back(std::move(cells));
  }
  return t;
}

ResultSet read_result(const fs::path& dir) {
  ResultSet r;
  r.dir = dir;
  if (const auto problems = silodem::verify_manifest(dir); !problems.empty()) {
    std::string why = dir.string() + " does not verify against its manifest, so it is not read:";
    for (const auto& p : problems) why += "\n  " + p;
    throw std::runtime_error(why);
  }
  std::ifstream in(dir / "summary.json");
  if (!in) throw std::runtime_error("no summary.json in " + dir.string());
  r.summary = nlohmann::json::parse(in);
  if (r.summary.value("status", "") != "complete")
    throw std::runtime_error(dir.string() + " holds an incomplete result (status " + r.summary.value("status", "?") + ")");
  return r;
}

const nlohmann::json& ResultSet::probe_digest(const std::string& name) const {
  const auto& p = summary.at("probes");
  if (!p.contains(name)) throw std::runtime_error("result has no probe \"" + name + "\"");
  return p.at(name);
}

CsvTable ResultSet::probe(const std::string& name) const {
  return read_csv(dir / "probes" / probe_digest(name).at("file").get<std::string>());
}

}  // namespace harness
