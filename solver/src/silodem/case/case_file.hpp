#pragma once
// Reading a case file's text with bounded resources: only a regular file is read (a FIFO would
// block, a device such as /dev/zero never ends), and never more than limits::kCaseFileBytes.
#include <filesystem>
#include <string>

namespace silodem {

/// The whole text of `file`; a CaseError naming the file if it cannot be opened, is not a regular
/// file, or is larger than limits::kCaseFileBytes (with the line and column where it passes it).
std::string read_case_text(const std::filesystem::path& file);

}  // namespace silodem
