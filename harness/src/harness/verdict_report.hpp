#pragma once
// The verdict table: one line per (case, variant, quantity) with the worst case among its rows,
// printed to stdout and written as Markdown; every row also goes to a JSON file.
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
