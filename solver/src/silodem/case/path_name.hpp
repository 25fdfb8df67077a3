#pragma once
// Names that become file or directory names (a case's name, a probe's, a variant's axis and
// value): checked where they are read, so that no name can reach outside the result directory,
// hide a file or be too long for the filesystem (docs/case-format.md, "Names").
#include <string>

namespace silodem {

/// Why `name` cannot be one component of a path, or "" if it can: it must be 1 to
/// limits::kNameBytes bytes, not begin with '.' (so never "." or ".."), and hold no '/', '\\',
/// NUL or other control character.
std::string path_name_problem(const std::string& name);

/// Throws a CaseError naming `json_path` if `name` cannot be one component of a path.
void require_path_name(const std::string& name, const std::string& json_path);

}  // namespace silodem
