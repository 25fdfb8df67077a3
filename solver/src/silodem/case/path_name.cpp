#include "silodem/case/path_name.hpp"

#include <nlohmann/json.hpp>

#include "silodem/case/case_error.hpp"
#include "silodem/case/limits.hpp"

namespace silodem {

std::string path_name_problem(const std::string& name) {
  if (name.empty()) return "must not be empty";
  if (name.size() > limits::kNameBytes)
    return "is " + std::to_string(name.size()) + " bytes long, more than the " + std::to_string(limits::kNameBytes) +
           " a file name may take here";
  if (name == "." || name == "..") return "is \"" + name + "\", which names a directory, not a new one";
  if (name[0] == '.') return "must not begin with '.' (it would make a hidden file)";
  for (const char c : name) {
    if (c == '/' || c == '\\') return std::string("must not contain '") + c + "' (a path separator)";
    const unsigned char u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) return "must not contain a control character (byte " + std::to_string(u) + ")";
  }
  return "";
}

void require_path_name(const std::string& name, const std::string& json_path) {
  const std::string problem = path_name_problem(name);
  if (problem.empty()) return;
  // Shown as JSON (escaped), so a control character in it cannot garble the terminal.
  const std::string shown = nlohmann::json(name.substr(0, 2 * limits::kNameBytes))
                                .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  throw CaseError(json_path, "the name " + shown + (name.size() > 2 * limits::kNameBytes ? "..." : "") +
                                 " becomes a file or directory name and " + problem);
}

}  // namespace silodem
