#include "harness/taken_rows.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "silodem/case/case_error.hpp"

namespace harness {

std::vector<CheckRow> read_spread_rows(const std::filesystem::path& file) {
  using nlohmann::json;
  const std::string where = file.string() + " (--material-tests-from)";
  std::ifstream in(file);
  if (!in) throw silodem::CaseError(where, "cannot be read: give the verdicts.json of an earlier silodem verify");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw silodem::CaseError(where, std::string("is not JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("rows") || !j["rows"].is_array())
    throw silodem::CaseError(where, "has no \"rows\" array: not a verdicts.json that silodem verify wrote");
  std::vector<CheckRow> out;
  for (const auto& r : j["rows"]) {
    const std::string q = r.value("quantity", "");
    if (r.value("code", "") != "silodem" || q.size() < 7 || q.compare(q.size() - 7, 7, "_spread") != 0) continue;
    if (!r.contains("expected") || !r["expected"].is_number() || !r.contains("measured") || !r["measured"].is_number())
      continue;  // a group whose tests gave no value (null): as if not measured
    CheckRow x;
    x.case_name = r.value("case", ""), x.variant = r.value("variant", ""), x.quantity = q;
    x.subject = r.value("subject", ""), x.note = r.value("note", "");
    x.expected = r["expected"].get<double>(), x.measured = r["measured"].get<double>();
    x.kind = RowKind::Report;
    x.reason = "taken from " + file.string();
    out.push_back(x);
  }
  if (out.empty()) throw silodem::CaseError(where, "holds no material test's spread rows");
  return out;
}

}  // namespace harness
