#include "harness/verdict_report.hpp"
#include "silodem/output/checked_file.hpp"
#include "silodem/output/result_dir.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <map>
#include <ostream>

namespace harness {

namespace {

struct Line {
  std::string case_name, variant, code, quantity;
  std::size_t n = 0, passed = 0, skipped = 0;
  CheckRow worst;
  double worst_ratio = -1.0;
  std::string verdict() const {
    if (skipped == n) return "skip";
    return passed + skipped == n ? "pass" : "fail";
  }
};

/// Rows grouped by (case, variant, code, quantity); the worst row is the failing one with the
/// largest error/tolerance, or the passing one closest to its tolerance.
std::vector<Line> group(const std::vector<CheckRow>& rows) {
  std::vector<Line> lines;
  std::map<std::string, std::size_t> index;
  for (const auto& r : rows) {
    const std::string key = r.case_name + "|" + r.variant + "|" + r.code + "|" + r.quantity;
    auto it = index.find(key);
    if (it == index.end()) {
      it = index.emplace(key, lines.size()).first;
      Line fresh;
      fresh.case_name = r.case_name;
      fresh.variant = r.variant;
      fresh.code = r.code;
      fresh.quantity = r.quantity;
      lines.push_back(fresh);
    }
    Line& l = lines[it->second];
    ++l.n;
    l.passed += r.pass && !r.skipped;
    l.skipped += r.skipped;
    double ratio = r.skipped ? -0.5 : r.tolerance > 0.0 ? std::abs(r.error) / r.tolerance : (r.pass ? 0.0 : 1e300);
    if (!std::isfinite(ratio)) ratio = 1e300;
    if (!r.pass && !r.skipped) ratio += 1e6;
    if (ratio > l.worst_ratio) l.worst_ratio = ratio, l.worst = r;
  }
  return lines;
}

std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

std::string count(const Line& l) {
  return "(" + std::to_string(l.passed) + "/" + std::to_string(l.n - l.skipped) + ")";
}

}  // namespace

bool VerifyOutcome::all_pass() const {
  std::size_t judged = 0;
  for (const auto& r : rows) {
    if (r.skipped) continue;
    ++judged;
    if (!r.pass) return false;
  }
  return judged > 0;
}

void print_verdicts(std::ostream& os, const VerifyOutcome& v) {
  char buf[1024];
  std::snprintf(buf, sizeof buf, "%-22s %-34s %-20s %-26s %-18s %13s %13s %11s %10s %s\n", "case", "variant", "code",
                "quantity", "worst subject", "expected", "measured", "error", "tolerance", "verdict");
  os << buf;
  for (const auto& l : group(v.rows)) {
    if (l.verdict() == "skip" || (l.quantity == "run" && l.verdict() == "fail")) {
      std::snprintf(buf, sizeof buf, "%-22s %-34s %-20s %-26s %s: %s\n", l.case_name.c_str(), l.variant.c_str(),
                    l.code.c_str(), l.quantity.c_str(), l.verdict() == "skip" ? "SKIP" : "FAIL", l.worst.note.c_str());
    } else {
      std::snprintf(buf, sizeof buf, "%-22s %-34s %-20s %-26s %-18s %13.6g %13.6g %11.3e %10.3e %s %s\n",
                    l.case_name.c_str(), l.variant.c_str(), l.code.c_str(), l.quantity.c_str(),
                    l.worst.subject.c_str(), l.worst.expected, l.worst.measured, l.worst.error, l.worst.tolerance,
                    l.verdict() == "pass" ? "PASS" : "FAIL", count(l).c_str());
    }
    os << buf;
  }
  std::size_t pass = 0, skip = 0;
  for (const auto& r : v.rows) pass += r.pass && !r.skipped, skip += r.skipped;
  os << (v.all_pass() ? "ALL PASS" : "FAILURES") << ": " << pass << " of " << v.rows.size() - skip
     << " checks passed, " << skip << " skipped\n";
}

void write_verdict_json(const std::filesystem::path& file, const VerifyOutcome& v) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : v.rows)
    rows.push_back({{"case", r.case_name}, {"variant", r.variant}, {"code", r.code}, {"quantity", r.quantity},
                    {"subject", r.subject}, {"expected", r.expected}, {"measured", r.measured}, {"error", r.error},
                    {"tolerance", r.tolerance}, {"verdict", r.verdict()}, {"note", r.note}});
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& [name, s] : v.run_seconds) runs.push_back({{"run", name}, {"wall_seconds", s}});
  silodem::write_file_checked(file, nlohmann::json{{"all_pass", v.all_pass()}, {"rows", rows}, {"runs", runs}}.dump(1) + "\n");
}

void write_verdict_markdown(const std::filesystem::path& file, const VerifyOutcome& v, const std::string& title,
                            const std::string& preamble) {
  std::ostringstream md;
  md << silodem::report_marker_line() << "\n";
  std::size_t pass = 0, skip = 0;
  for (const auto& r : v.rows) pass += r.pass && !r.skipped, skip += r.skipped;
  md << "# " << title << "\n\n" << preamble << "\n\n" << pass << " of " << v.rows.size() - skip
     << " checks passed, " << skip << " skipped: **" << (v.all_pass() ? "ALL PASS" : "FAILURES") << "**.\n\n"
     << "Each line is the worst of its rows (largest error relative to tolerance). Errors are relative "
        "(measured/expected − 1) except for `integrated_contact_height` (m), `energy_drift` (fraction of "
        "the energy moved), `captured_gap/reach` and the yes/no checks (obstacle choice); `*_order` lines "
        "give the observed order of the worst error between two time steps and pass when the error "
        "falls. A skipped line gives its reason.\n\n"
     << "| case | variant | code | quantity | worst subject | expected | measured | error | tolerance | verdict |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& l : group(v.rows)) {
    if (l.verdict() == "skip" || (l.quantity == "run" && l.verdict() == "fail")) {
      std::string note = l.worst.note;
      for (char& ch : note) ch = ch == '\n' ? ' ' : ch == '|' ? '/' : ch;
      md << "| " << l.case_name << " | " << l.variant << " | " << l.code << " | " << l.quantity << " | | | | | | "
         << (l.verdict() == "skip" ? "skip: " : "**FAIL**: ") << note << " |\n";
      continue;
    }
    md << "| " << l.case_name << " | " << l.variant << " | " << l.code << " | " << l.quantity << " | "
       << l.worst.subject << " | " << fmt(l.worst.expected) << " | " << fmt(l.worst.measured) << " | "
       << fmt(l.worst.error) << " | " << fmt(l.worst.tolerance) << " | "
       << (l.verdict() == "pass" ? "pass" : "**FAIL**") << " " << count(l) << " |\n";
  }
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
