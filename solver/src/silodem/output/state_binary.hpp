#pragma once
// The compact state file `silodem-state/2` (docs/case-format.md "Compact state files"): one line
// of JSON naming the columns, their types, units and byte ranges, then the columns themselves,
// raw little-endian, one after another. About 90 bytes per ball against state.json's 230, and
// read without a JSON parser: what a 10^6-ball case or continuation loads from.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

struct StateSnapshot;

inline constexpr const char* kStateBinaryFormat = "silodem-state/2";

/// Whether `file` starts like a compact state file (its first bytes are `{"format":"silodem-state/2"`).
bool is_binary_state(const std::filesystem::path& file);

/// Writes the balls of `p` in tag order, atomically (temporary file, then rename).
void write_state_binary(const std::filesystem::path& file, const std::string& case_name, double dt,
                        const Particles& p, const std::vector<std::string>& material_names, long step, double t);

/// Reads a compact state; throws CaseError naming the file and what is wrong with it (a truncated
/// file, a column of the wrong size, an unknown material index, a non-finite value).
StateSnapshot read_state_binary(const std::filesystem::path& file);

}  // namespace silodem
