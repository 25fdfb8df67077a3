#pragma once
// What the whole-run tests of the solver share: a case run into its own scratch directory, and the
// loader's refusal of a case as text.
#include <filesystem>
#include <string>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace silodem_test {

/// Runs the case into <tmp>/<scratch> (emptied first: the test's own directory); its summary.
inline nlohmann::json run_in_scratch(const nlohmann::json& c, const std::string& scratch) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / scratch;
  std::filesystem::remove_all(out);
  return silodem::run_case(silodem::load_case(c), {out, false, false});
}

/// The loader's message refusing the case, or "" when it loads.
inline std::string refusal(const nlohmann::json& c) {
  try {
    silodem::load_case(c);
  } catch (const silodem::CaseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace silodem_test
