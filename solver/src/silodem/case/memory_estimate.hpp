#pragma once
// The memory a run of a case will hold, estimated from the case alone before anything is built,
// so that a count no machine can hold (drops.count = 1e9) is refused naming its field instead of
// ending the run in std::bad_alloc. What is counted, and the sizes: docs/case-format.md ("Limits").
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"

namespace silodem {

struct MemoryTerm {
  std::string what;   // "1000000 drops (drops.count)", for messages
  std::string field;  // the JSON path to change to make it smaller
  double bytes = 0.0;
};

struct MemoryEstimate {
  std::vector<MemoryTerm> terms;
  double total() const;
  const MemoryTerm& largest() const;
  /// "12.3 MiB (drops 10.1 MiB, case file as parsed 1.2 MiB, ...)", the largest terms first.
  std::string describe() const;
};

/// The run's peak: ball arrays, integrator state, neighbour list (pairs per ball estimated from
/// the radii, skin and cohesion reach), the case as parsed (held twice: the case and the summary's
/// copy), probe records that grow with the drops, and the final state file as it is written.
/// Records that grow with events the case does not bound (contacts of a pair probe, exits of a
/// recycling outflow) are not counted.
MemoryEstimate estimate_run_memory(const CaseConfig& cfg);

struct MemoryLimit {
  double bytes = 0.0;
  std::string source;  // "the stated limit of 64 GiB" or where the machine's figure came from
};

/// The lower of limits::kRunMemoryBytes and what this machine has available now.
MemoryLimit run_memory_limit();

/// Refuses a case whose estimate is above `limit`: a CaseError naming the field of the largest term.
void check_run_memory(const CaseConfig& cfg, const MemoryLimit& limit);

/// Heap bytes of a parsed JSON value as nlohmann-json holds it on libstdc++ (map nodes, element
/// arrays grown by doubling, string objects; malloc's rounding included).
double json_heap_bytes(const nlohmann::json& j);

/// Refuses (CaseError naming "$") a parsed case that could not be copied into its CaseConfig in
/// what this process can still take; checked before the copy is made.
void check_case_copy_fits(const nlohmann::json& j);

/// Bytes as "512 B", "1.5 KiB", "12.3 MiB", "4.00 GiB".
std::string format_bytes(double bytes);

}  // namespace silodem
