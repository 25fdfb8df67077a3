#pragma once
// Verification checks: each compares one physical quantity of a finished run (read from its
// result files) with a closed-form oracle from references/, and says pass or fail with the
// numbers. The check list is data in the case file ("verify.checks").
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "harness/result_files.hpp"
#include "silodem/case/case_config.hpp"

namespace harness {

struct CheckRow {
  std::string case_name;
  std::string variant;
  std::string code = "silodem";  // the code whose result the row judges ("silodem vs lammps" for cross-code rows)
  std::string quantity;   // "restitution", "contact_duration", ...
  std::string subject;    // probe or pair the row is about
  double expected = 0.0;
  double measured = 0.0;
  double error = 0.0;     // relative unless `absolute`
  double tolerance = 0.0;
  bool pass = false;
  bool skipped = false;   // not run (code not found, case not representable): neither pass nor fail
  std::string note;       // for a skipped row: the reason
  std::string verdict() const { return skipped ? "skip" : pass ? "pass" : "fail"; }
};

struct RunContext {
  const silodem::CaseConfig& cfg;
  const ResultSet& result;
  std::string variant;
  std::string code = "silodem";
};

/// A row judged by |error| ≤ tolerance, error = (measured − expected)/expected (or the plain
/// difference when `relative` is false).
CheckRow make_row(const RunContext& ctx, std::string quantity, std::string subject, double expected, double measured,
                  double tolerance, bool relative = true);

/// Validates one entry of verify.checks (throws CaseError with its JSON path).
/// `axes` are the variant axes of the case (a convergence check must name one of them).
void validate_check(const nlohmann::json& spec, const std::string& path, const silodem::CaseConfig& cfg,
                    const std::vector<std::string>& axes);

/// Runs one per-run check; "convergence" checks are not per-run and return nothing here.
std::vector<CheckRow> run_check(const nlohmann::json& spec, const RunContext& ctx);

/// The wall the outlet is cut into: its hole diameter D_0.
double outlet_diameter(const nlohmann::json& spec, const silodem::CaseConfig& cfg);

/// Beverloo across the outlets of a variant axis: fits C and k of W = C ρ_b √g (D_0 − k d)^{5/2}.
std::vector<CheckRow> beverloo_fit_rows(const nlohmann::json& spec, const std::string& case_name,
                                       const std::vector<CheckRow>& rows, const std::vector<std::string>& variants,
                                       const std::vector<double>& outlets, double g);

/// Convergence along the time-step axis: for every group of variants that differ only in `axis`,
/// the largest error of `quantity` must fall as dt falls; reports the observed order.
std::vector<CheckRow> convergence_rows(const nlohmann::json& spec, const std::string& case_name,
                                       const std::vector<CheckRow>& rows,
                                       const std::vector<std::pair<std::string, std::string>>& variant_groups,
                                       const std::vector<double>& variant_dt);

}  // namespace harness
