#include "harness/verdict_report.hpp"

#include "silodem/output/checked_file.hpp"
#include "silodem/output/result_dir.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <ostream>

#include "harness/verdict_counts.hpp"

namespace harness {

namespace {

/// How far a row is from failing: > 1 fails, 1 is at the limit, 0 is dead on.
double closeness(const CheckRow& r) {
  if (!r.pass) return std::isfinite(r.error) ? 1e6 + std::abs(r.error) : 1e300;
  if (r.kind == RowKind::Match) return r.tolerance > 0.0 ? std::abs(r.error) / r.tolerance : 0.0;
  const double margin = r.side == BoundSide::Upper ? r.bound - r.measured : r.measured - r.bound;
  return 1.0 - margin / std::max({std::abs(r.bound), std::abs(r.measured), 1e-300});
}

/// The judged line's worst row: the failing one with the largest error, or the passing one closest to its limit.
const CheckRow& worst(const QuantityLine& l) {
  const CheckRow* w = l.rows.front();
  for (const CheckRow* r : l.rows)
    if (closeness(*r) > closeness(*w)) w = r;
  return *w;
}

std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

std::string limit(const CheckRow& r) {
  if (r.kind == RowKind::Bound) return (r.side == BoundSide::Upper ? "<= " : ">= ") + fmt(r.bound);
  return "|e| <= " + fmt(r.tolerance);
}

std::string count(const QuantityLine& l) {
  return "(" + std::to_string(l.passed) + "/" + std::to_string(l.rows.size()) + ")";
}

/// Text for a Markdown table cell: one line, pipes escaped.
std::string cell(const std::string& s) {
  std::string out;
  for (char ch : s) out += ch == '\n' ? std::string(" ") : ch == '|' ? std::string("\\|") : std::string(1, ch);
  return out;
}

/// Text for a Markdown list item: one line.
std::string line(std::string s) {
  for (char& ch : s) ch = ch == '\n' ? ' ' : ch;
  return s;
}

/// Numbered notes: each distinct text once, cited by its number.
struct Notes {
  std::vector<std::string> texts;
  std::map<std::string, std::size_t> index;
  std::string cite(const std::string& t) {
    auto it = index.find(t);
    if (it == index.end()) {
      it = index.emplace(t, texts.size()).first;
      texts.push_back(t);
    }
    return "[" + std::to_string(it->second + 1) + "]";
  }
};

}  // namespace

bool VerifyOutcome::all_pass() const { return headline(rows).total.all_pass(); }

void print_verdicts(std::ostream& os, const VerifyOutcome& v) {
  char buf[1200];
  std::snprintf(buf, sizeof buf, "%-22s %-34s %-20s %-26s %-6s %-18s %13s %13s %11s %16s %s\n", "case", "variant", "code",
                "quantity", "kind", "worst subject", "expected", "measured", "error", "limit", "verdict");
  os << buf;
  const auto lines = quantity_lines(v.rows);
  for (const auto& l : lines) {
    if (l.cls != "judged") continue;
    const CheckRow& w = worst(l);
    if (l.quantity == "run") {
      std::snprintf(buf, sizeof buf, "%-22s %-34s %-20s %-26s FAIL: %s\n", l.case_name.c_str(), l.variant.c_str(),
                    l.code.c_str(), l.quantity.c_str(), w.note.c_str());
    } else {
      std::snprintf(buf, sizeof buf, "%-22s %-34s %-20s %-26s %-6s %-18s %13.6g %13.6g %11.3e %16s %s %s\n",
                    l.case_name.c_str(), l.variant.c_str(), l.code.c_str(), l.quantity.c_str(), kind_name(w.kind).c_str(),
                    w.subject.c_str(), w.expected, w.measured, w.error, limit(w).c_str(), l.pass() ? "PASS" : "FAIL",
                    count(l).c_str());
    }
    os << buf;
  }
  for (const auto& l : lines) {
    if (l.cls == "judged") continue;
    const CheckRow& r = *l.rows.front();
    std::snprintf(buf, sizeof buf, "%-22s %-34s %-20s %-26s %s: %s\n", l.case_name.c_str(), l.variant.c_str(),
                  l.code.c_str(), l.quantity.c_str(), l.cls == "skip" ? "SKIP" : "REPORT",
                  (l.cls == "skip" ? r.note : r.reason).c_str());
    os << buf;
  }
  const Headline h = headline(v.rows);
  os << (h.total.all_pass() ? "ALL PASS" : "FAILURES") << ": " << headline_sentence(h.total) << "\n";
}

void write_verdict_json(const std::filesystem::path& file, const VerifyOutcome& v) {
  using nlohmann::json;
  json rows = json::array();
  for (const auto& r : v.rows) {
    json j = {{"case", r.case_name}, {"variant", r.variant}, {"code", r.code}, {"quantity", r.quantity},
              {"subject", r.subject}, {"kind", kind_name(r.kind)}, {"expected", r.expected}, {"measured", r.measured},
              {"error", r.error}, {"tolerance", r.tolerance}, {"verdict", r.verdict()}, {"note", r.note}};
    if (r.kind == RowKind::Bound) j["bound"] = r.bound, j["side"] = side_name(r.side);
    if (r.kind == RowKind::Report) j["reason"] = r.reason;
    else j["tolerance_source"] = r.tolerance_source;
    rows.push_back(j);
  }
  const auto counts = [](const VerdictCounts& c) {
    return json{{"variants", c.variants},          {"judged_quantities", c.judged},
                {"judged_quantities_passed", c.judged_passed}, {"judged_rows", c.rows},
                {"judged_rows_passed", c.rows_passed}, {"report_quantities", c.reported},
                {"report_rows", c.report_rows},      {"skipped_rows", c.skipped_rows}};
  };
  const Headline h = headline(v.rows);
  json per_case = json::array();
  for (const auto& [name, c] : h.cases) {
    json j = counts(c);
    j["case"] = name;
    per_case.push_back(j);
  }
  json runs = json::array();
  for (const auto& [name, s] : v.run_seconds) runs.push_back({{"run", name}, {"wall_seconds", s}});
  silodem::write_file_checked(file, json{{"all_pass", h.total.all_pass()},
                                          {"headline", {{"total", counts(h.total)}, {"cases", per_case}}},
                                          {"rows", rows},
                                          {"runs", runs}}
                                         .dump(1) +
                                     "\n");
}

void write_verdict_markdown(const std::filesystem::path& file, const VerifyOutcome& v, const std::string& title,
                            const std::string& preamble) {
  std::ostringstream md;
  md << silodem::report_marker_line() << "\n";
  const Headline h = headline(v.rows);
  md << "# " << title << "\n\n" << preamble << "\n\n**" << (h.total.all_pass() ? "ALL PASS" : "FAILURES") << "**: "
     << headline_sentence(h.total) << ".\n\n"
     << "A judged quantity is one (case, variant, code, quantity): it passes when all its sub-rows (pairs, "
        "probes, bands) pass. Only `match` rows (two-sided: |error| ≤ tolerance) and `bound` rows (one-sided: "
        "measured ≤ or ≥ a bound) are judged, and only when their tolerance states its source — a scheme's error "
        "bound, a measured seed scatter or a published range, listed under the tables. `report` rows give a "
        "measured figure without a verdict, with the reason (docs/case-format.md, \"Row kinds\").\n\n"
     << "| case | variants | judged quantities passed | judged sub-rows passed | reported quantities (rows) | skipped rows |\n"
     << "|---|---|---|---|---|---|\n";
  for (const auto& [name, c] : h.cases)
    md << "| " << name << " | " << c.variants << " | " << c.judged_passed << " / " << c.judged << " | " << c.rows_passed
       << " / " << c.rows << " | " << c.reported << " (" << c.report_rows << ") | " << c.skipped_rows << " |\n";
  md << "\n## Judged\n\nEach line is the worst of its sub-rows (a failing one, or the one closest to its limit). "
        "Errors are relative (measured/expected − 1) unless the check documents them as absolute; a bound "
        "row's error is measured − bound.\n\n"
     << "| case | variant | code | quantity | kind | worst subject | expected | measured | error | limit | verdict | source |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  Notes sources, reasons;
  const auto lines = quantity_lines(v.rows);
  for (const auto& l : lines) {
    if (l.cls != "judged") continue;
    const CheckRow& w = worst(l);
    md << "| " << l.case_name << " | " << l.variant << " | " << l.code << " | " << l.quantity << " | "
       << kind_name(w.kind) << " | ";
    if (l.quantity == "run")
      md << " | | | | | **FAIL**: " << cell(w.note) << " | |\n";
    else
      md << w.subject << " | " << fmt(w.expected) << " | " << fmt(w.measured) << " | " << fmt(w.error) << " | "
         << cell(limit(w)) << " | " << (l.pass() ? "pass" : "**FAIL**") << " " << count(l) << " | "
         << sources.cite(w.tolerance_source) << " |\n";
  }
  md << "\n## Reported, not judged\n\n"
     << "| case | variant | code | quantity | first subject | expected | measured | rows | reason |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& l : lines) {
    if (l.cls != "report") continue;
    const CheckRow& r = *l.rows.front();
    md << "| " << l.case_name << " | " << l.variant << " | " << l.code << " | " << l.quantity << " | " << r.subject
       << " | " << fmt(r.expected) << " | " << fmt(r.measured) << " | " << l.rows.size() << " | "
       << reasons.cite(r.reason) << " |\n";
  }
  bool any_skip = false;
  for (const auto& l : lines) any_skip = any_skip || l.cls == "skip";
  if (any_skip) {
    md << "\n## Skipped\n\n| case | variant | code | quantity | reason |\n|---|---|---|---|---|\n";
    for (const auto& l : lines)
      if (l.cls == "skip")
        md << "| " << l.case_name << " | " << l.variant << " | " << l.code << " | " << l.quantity << " | "
           << cell(l.rows.front()->note) << " |\n";
  }
  md << "\n### Sources of the tolerances\n\n";
  for (std::size_t i = 0; i < sources.texts.size(); ++i) md << i + 1 << ". " << line(sources.texts[i]) << "\n";
  md << "\n### Why the reported rows are not judged\n\n";
  for (std::size_t i = 0; i < reasons.texts.size(); ++i) md << i + 1 << ". " << line(reasons.texts[i]) << "\n";
  if (!v.ledgers.empty()) {
    md << "\n## Energy ledgers side by side\n\nFinal state of each run, rebuilt the same way for every code from "
          "its particle dumps (silodem: its own ledger, and in brackets the rebuilt one). J.\n\n"
       << "| case | variant | code | initial | kinetic | elastic | dissipated | balance | max drift |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& l : v.ledgers) md << "| " << l << " |\n";
  }
  double total = 0.0;
  for (const auto& [n, s] : v.run_seconds) total += s;
  md << "\n" << v.run_seconds.size() << " runs, " << fmt(total) << " s of wall time in total.\n";
  silodem::write_file_checked(file, md.str());
}

}  // namespace harness
