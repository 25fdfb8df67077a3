#pragma once
// One row of a verdict table and its kind (docs/case-format.md, "Row kinds"):
//   match  — two-sided: |error| ≤ tolerance;
//   bound  — one-sided: measured ≤ bound (upper) or measured ≥ bound (lower);
//   report — a measured figure with no verdict, and the reason why.
// Only match and bound rows pass or fail, and only when their tolerance or bound states its source
// (a scheme's error bound, a measured seed scatter with its number of realisations, or a cited
// published range): judge() turns a row without one into a report row.
#include <cmath>
#include <string>

namespace harness {

enum class RowKind { Match, Bound, Report };
enum class BoundSide { Upper, Lower };

std::string kind_name(RowKind kind);  // "match", "bound", "report"
std::string side_name(BoundSide side);  // "upper", "lower"

struct CheckRow {
  std::string case_name;
  std::string variant;
  std::string code = "silodem";  // the code whose result the row judges ("silodem vs lammps" for cross-code rows)
  std::string quantity;          // "restitution", "contact_duration", ...
  std::string subject;           // probe or pair the row is about
  RowKind kind = RowKind::Report;  // a row nobody classified is never counted as a pass
  double expected = NAN;
  double measured = NAN;
  double error = NAN;      // match: relative unless the note or docs say absolute; bound: measured − bound
  double tolerance = NAN;  // match: the verdict is |error| ≤ tolerance
  BoundSide side = BoundSide::Upper;
  double bound = NAN;            // bound: the verdict is measured ≤ bound (upper) or ≥ bound (lower)
  std::string tolerance_source;  // match, bound: where the tolerance or the bound comes from
  std::string reason;            // report: why the figure carries no verdict
  bool pass = false;
  bool skipped = false;  // not run (code not found, case not representable): neither pass nor fail
  std::string note;      // details; for a skipped row the reason

  /// Counts towards pass/fail: a match or bound row that was not skipped.
  bool judged() const { return !skipped && kind != RowKind::Report; }
  /// "skip", "report", "pass" or "fail".
  std::string verdict() const;
};

/// Sets the verdict from the kind (and the error of a bound row as its margin, measured − bound).
/// A match or bound row with no stated tolerance source becomes a report row saying so.
void judge(CheckRow& r);

/// Drops the verdict: the row becomes a report row with this reason (measured value kept).
void to_report(CheckRow& r, std::string reason);

/// A row for a run that did not produce results (crash, time-out, unreadable output): judged, failing.
CheckRow failed_run_row(std::string case_name, std::string variant, std::string code, std::string why);

}  // namespace harness
