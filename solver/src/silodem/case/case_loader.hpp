#pragma once
// Case file → validated CaseConfig. Every rejection is a CaseError naming the JSON path.
#include <filesystem>

#include "silodem/case/case_config.hpp"

namespace silodem {

CaseConfig load_case_file(const std::filesystem::path& file);
/// The file's JSON, or a CaseError naming the file (unreadable, malformed).
nlohmann::json read_case_json(const std::filesystem::path& file);
CaseConfig load_case(const nlohmann::json& j);

}  // namespace silodem
