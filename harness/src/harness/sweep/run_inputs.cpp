#include "harness/sweep/run_inputs.hpp"

#include "silodem/case/case_loader.hpp"
#include "silodem/output/manifest.hpp"

namespace harness {

nlohmann::json without_judging(nlohmann::json case_json) {
  if (!case_json.is_object()) return case_json;
  case_json.erase("verify");
  if (auto c = case_json.find("compare"); c != case_json.end() && c->is_object())
    for (const char* key : {"checks", "between_codes", "time_limit_s"}) c->erase(key);
  return case_json;
}

std::string run_digest(const std::filesystem::path& case_file) {
  return silodem::text_digest(without_judging(silodem::read_case_json(case_file)).dump());
}

}  // namespace harness
