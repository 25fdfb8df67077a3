#pragma once
// Material-test rows taken from an earlier verify (`silodem verify --material-tests-from
// DIR/verdicts.json`): a silo case whose checks take the virtual material tests (janssen_prediction,
// flow_pattern) can be rerun against tests measured before, without rerunning an hour of them.
#include <filesystem>
#include <vector>

#include "harness/check_row.hpp"

namespace harness {

/// The spread rows (mean over a material group, its scatter, "N realisations") of silodem in a
/// verdicts.json that verify wrote. Throws silodem::CaseError naming the file if it is missing, not
/// such a file, or holds no spread row. The rows come back as report rows: figures taken, never
/// counted again as verdicts of this run.
std::vector<CheckRow> read_spread_rows(const std::filesystem::path& verdicts_json);

}  // namespace harness
