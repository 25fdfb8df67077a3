#include "harness/case_names.hpp"

#include <map>

#include "silodem/case/case_error.hpp"

namespace harness {

void require_distinct_case_names(const std::vector<std::filesystem::path>& files, const std::vector<std::string>& names) {
  std::map<std::string, std::size_t> first;  // name → index of the file that gave it first
  for (std::size_t i = 0; i < names.size() && i < files.size(); ++i) {
    const auto [it, fresh] = first.emplace(names[i], i);
    if (fresh) continue;
    const std::string other = files[it->second].string();
    throw silodem::CaseError(files[i].string() + " $.name",
                             "the case name \"" + names[i] + "\" is also the name of the case in " +
                                 (other == files[i].string() ? "the same file, given twice" : other) +
                                 ": each case writes its results to <out>/<name>/, so the names of the cases of "
                                 "one call must differ");
  }
}

}  // namespace harness
