#pragma once
// The verdict table: a headline of judged quantities per case (verdict_counts.hpp), then one line
// per judged (case, variant, code, quantity) with its worst row, and the report rows apart with
// their reasons; printed to stdout and written as Markdown. Every row, with its kind and its
// tolerance's source or its reason, also goes to verdicts.json.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "harness/verify.hpp"

namespace harness {

void print_verdicts(std::ostream& os, const VerifyOutcome& v);
void write_verdict_json(const std::filesystem::path& file, const VerifyOutcome& v);
void write_verdict_markdown(const std::filesystem::path& file, const VerifyOutcome& v, const std::string& title,
                            const std::string& preamble);

}  // namespace harness
