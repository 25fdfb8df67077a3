#pragma once
// One `verify` or `compare` call writes each case's results to <out>/<case name>/: two case files
// with one name would overwrite each other's results, so they are refused before anything runs.
#include <filesystem>
#include <string>
#include <vector>

namespace harness {

/// names[i] is the name of the case in files[i]; a repeated name is a silodem::CaseError naming
/// both files.
void require_distinct_case_names(const std::vector<std::filesystem::path>& files, const std::vector<std::string>& names);

}  // namespace harness
