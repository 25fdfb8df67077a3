#pragma once
// Case-file text → JSON, refusing what nlohmann::json would silently accept: a key given twice
// in one object (the parser keeps the last, so the first value would be ignored unseen), and
// nesting deeper than any case needs.
#include <nlohmann/json.hpp>

#include <string>

namespace silodem {

/// Parses `text`; a syntax error, or arrays and objects nested deeper than limits::kJsonDepth,
/// is a CaseError naming `source` with the line and column, a duplicated key a CaseError naming
/// its JSON path. The memory it holds besides the result is linear in the text.
nlohmann::json parse_case_text(const std::string& text, const std::string& source);

}  // namespace silodem
