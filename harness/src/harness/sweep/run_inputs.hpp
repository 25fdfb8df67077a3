#pragma once
// What a run reads of its case: a resumed sweep (--resume) keeps a run whose case changed only in
// how its results are judged (checks, tolerances, between-codes rows, the time limit), so that a
// tolerance re-derived from new measurements does not rerun hours of reference codes. Any change of
// the scene, the stages, the output or the seeds runs it again.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace harness {

/// The case without its judging: `verify` (its checks; verify's variants are already applied to a
/// variant's JSON), and compare's `checks`, `between_codes` and `time_limit_s`.
nlohmann::json without_judging(nlohmann::json case_json);

/// "<bytes>:<CRC-32>" of the case file as read (read_case_json) without its judging.
std::string run_digest(const std::filesystem::path& case_file);

}  // namespace harness
