#include "harness/check_row.hpp"

#include "silodem/case/json_reader.hpp"

namespace harness {

std::string kind_name(RowKind kind) {
  switch (kind) {
    case RowKind::Match: return "match";
    case RowKind::Bound: return "bound";
    case RowKind::Report: break;
  }
  return "report";
}

std::string side_name(BoundSide side) { return side == BoundSide::Upper ? "upper" : "lower"; }

std::string CheckRow::verdict() const {
  if (skipped) return "skip";
  if (kind == RowKind::Report) return "report";
  return pass ? "pass" : "fail";
}

void to_report(CheckRow& r, std::string reason) {
  r.kind = RowKind::Report;
  r.reason = std::move(reason);
  r.pass = false;
}

void judge(CheckRow& r) {
  if (r.kind != RowKind::Report && r.tolerance_source.empty()) {
    const double t = r.kind == RowKind::Match ? r.tolerance : r.bound;
    to_report(r, "tolerance " + silodem::format_number(t) +
                     " has no stated source (a scheme's error bound, a measured seed scatter or a published range: "
                     "docs/case-format.md, \"Tolerance sources\")");
    return;
  }
  switch (r.kind) {
    case RowKind::Match:
      r.pass = std::isfinite(r.error) && std::abs(r.error) <= r.tolerance;
      break;
    case RowKind::Bound:
      r.error = r.measured - r.bound;
      r.pass = std::isfinite(r.measured) && (r.side == BoundSide::Upper ? r.measured <= r.bound : r.measured >= r.bound);
      break;
    case RowKind::Report:
      r.pass = false;
      break;
  }
}

CheckRow failed_run_row(std::string case_name, std::string variant, std::string code, std::string why) {
  CheckRow r;
  r.case_name = std::move(case_name);
  r.variant = std::move(variant);
  r.code = std::move(code);
  r.quantity = "run";
  r.kind = RowKind::Match;
  r.expected = 1.0;  // a complete run
  r.measured = 0.0;
  r.error = NAN;
  r.tolerance = 0.0;
  r.tolerance_source = "a run that produced no result fails";
  r.note = std::move(why);
  r.pass = false;
  return r;
}

}  // namespace harness
