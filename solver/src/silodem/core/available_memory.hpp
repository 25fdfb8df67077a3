#pragma once
// How much memory this process can still take: the least of the kernel's MemAvailable, the
// cgroup's memory.max less its usage (a container or a batch job's share), and the address-space
// limit (ulimit -v) less what the process maps already.
#include <optional>
#include <string>

namespace silodem {

struct AvailableMemory {
  double bytes = 0.0;
  std::string source;  // which of the three it is, for messages: "MemAvailable in /proc/meminfo", ...
};

/// The tightest of the three that can be read; none readable: nullopt.
std::optional<AvailableMemory> available_memory();

}  // namespace silodem
