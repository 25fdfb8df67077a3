#pragma once
// Verification checks: each compares one physical quantity of a finished run (read from its
// result files) with a closed-form oracle from references/. A row is judged (match or bound) only
// when its tolerance has a source; otherwise it reports the figure (check_row.hpp). The check list
// is data in the case file ("verify.checks").
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "harness/check_row.hpp"
#include "harness/result_files.hpp"
#include "silodem/case/case_config.hpp"

namespace harness {

struct RunContext {
  const silodem::CaseConfig& cfg;
  const ResultSet& result;
  std::string variant;
  std::string code = "silodem";
  const std::vector<CheckRow>* earlier_rows = nullptr;  // rows of the cases verify ran before this one
};

/// A listed ball of the case by id (throws if none), and its mass from its material's density.
const silodem::BallSpec& ball(const silodem::CaseConfig& cfg, const std::string& id);
double mass(const silodem::CaseConfig& cfg, const silodem::BallSpec& b);

/// A match row, judged by |error| ≤ tolerance with error = (measured − expected)/expected (or the
/// plain difference when `relative` is false); `source` says where the tolerance comes from ("":
/// none, and the row is a report row).
CheckRow match_row(const RunContext& ctx, std::string quantity, std::string subject, double expected, double measured,
                   double tolerance, std::string source, bool relative = true);

/// A bound row: measured ≤ bound (Upper) or measured ≥ bound (Lower), with the bound's source.
CheckRow bound_row(const RunContext& ctx, std::string quantity, std::string subject, double measured, BoundSide side,
                   double bound, std::string source);

/// A report row: the figure, and why it carries no verdict.
CheckRow report_row(const RunContext& ctx, std::string quantity, std::string subject, double measured,
                    std::string reason, double expected = NAN);

/// The reason a check on frictionless grains reports instead of judging `what` (Beverloo's C and k,
/// Janssen's K and μ_w, EN 1991-4 ratios): their published values are for frictional grains.
std::string frictionless_reason(const std::string& what);
/// True for a row reported for that reason (cross-code rows of such a quantity report it too).
bool is_frictionless_report(const CheckRow& r);
/// Whether the case's grains have contact friction. The model has none (docs/model.md), so every
/// grain is frictionless; the checks above become judged when frictional grains arrive.
bool frictional_grains(const silodem::CaseConfig& cfg);

/// Dump frames per contact of the shortest-lived pair the case can form: the resolution of a
/// ledger rebuilt from the dump (frames every max(1, dump_interval_steps) steps).
double energy_frames_per_contact(const silodem::CaseConfig& cfg);

/// Validates one entry of verify.checks (throws CaseError with its JSON path).
/// `axes` are the variant axes of the case (a convergence check must name one of them).
void validate_check(const nlohmann::json& spec, const std::string& path, const silodem::CaseConfig& cfg,
                    const std::vector<std::string>& axes);

/// Runs one per-run check; "convergence" checks are not per-run and return nothing here.
std::vector<CheckRow> run_check(const nlohmann::json& spec, const RunContext& ctx);

/// Runs every per-run check of `checks` (an array of specs) on one run, their rows in order.
std::vector<CheckRow> run_checks(const nlohmann::json& checks, const RunContext& ctx);

/// Where a column in a cylinder wall stands: the lowest disk (a floor) inside the cylinder's height,
/// or the cylinder's base without one (a mantle may reach below its floor, to slide past it).
double column_floor(const silodem::CaseConfig& cfg, const nlohmann::json& cylinder_geometry);

/// The wall the outlet is cut into: its hole diameter D_0.
/// The outlet diameter of a wall of balls (its hole_diameter) or of a smooth wall (twice the radius
/// of its lower end: a hopper's surface); 0 if the name is neither or has no outlet.
double outlet_diameter_of(const silodem::CaseConfig& cfg, const std::string& name);
double outlet_diameter(const nlohmann::json& spec, const silodem::CaseConfig& cfg);

/// Beverloo across the outlets of a variant axis: fits C and k of W = C ρ_b √g (D_0 − k d)^{5/2}.
/// For frictional grains C and k are judged within the spec's published "C_range" and "k_range".
std::vector<CheckRow> beverloo_fit_rows(const nlohmann::json& spec, const std::string& case_name,
                                       const std::vector<CheckRow>& rows, const std::vector<std::string>& variants,
                                       const std::vector<double>& outlets, double g, bool frictional);

/// Convergence along the time-step axis: for every group of variants that differ only in `axis`,
/// the largest error of `quantity` must fall as dt falls; reports the observed order.
std::vector<CheckRow> convergence_rows(const nlohmann::json& spec, const std::string& case_name,
                                       const std::vector<CheckRow>& rows,
                                       const std::vector<std::pair<std::string, std::string>>& variant_groups,
                                       const std::vector<double>& variant_dt);

/// The spread of measured quantities over a variant axis (the packings of a virtual material test):
/// for every group of variants that differ only in `axis`, one report row per quantity and subject
/// with expected = the mean, measured = the sample standard deviation, the realisations in the note.
std::vector<CheckRow> spread_rows(const nlohmann::json& spec, const std::string& case_name,
                                  const std::vector<CheckRow>& rows,
                                  const std::vector<std::pair<std::string, std::string>>& variant_groups);

}  // namespace harness
