// libFuzzer target: arbitrary bytes as a case file. Bad input must end in a CaseError (exit code
// 2 in the CLI); any other exception, a crash or a sanitizer report is a loader bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/case/json_text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    silodem::load_case(silodem::parse_case_text(text, "fuzz input"));
  } catch (const silodem::CaseError&) {
  }
  return 0;
}
