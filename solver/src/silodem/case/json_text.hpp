#pragma once
// Case-file text → JSON, refusing what nlohmann::json would silently accept: a key given twice
// in one object (the parser keeps the last, so the first value would be ignored unseen).
#include <nlohmann/json.hpp>

#include <string>

namespace silodem {

/// Parses `text`; a syntax error is a CaseError naming `source` with the line and column, a
/// duplicated key a CaseError naming its JSON path.
nlohmann::json parse_case_text(const std::string& text, const std::string& source);

}  // namespace silodem
