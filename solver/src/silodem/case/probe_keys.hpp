#pragma once
// The case file's probes (docs/case-format.md "output"): each probe's type and its keys, checked
// against the balls and walls already read. Read by case_loader.cpp; apart so that the loader
// stays one concept a file.
#include "silodem/case/case_config.hpp"
#include "silodem/case/json_reader.hpp"

namespace silodem::case_keys {

/// Reads output.probes into cfg.probes (the balls, walls, surfaces, drops and stages read already).
void read_probes(const JsonReader& r, CaseConfig& cfg);

}  // namespace silodem::case_keys
