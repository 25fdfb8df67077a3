#include "silodem/core/available_memory.hpp"

#include <sys/resource.h>

#include <fstream>
#include <sstream>

namespace silodem {

namespace {

/// The value of "Key:   123 kB" in a /proc file, in bytes.
std::optional<double> proc_kib(const char* file, const std::string& key) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ":", 0) == 0) {
      std::istringstream value(line.substr(key.size() + 1));
      double kib = 0.0;
      if (value >> kib) return kib * 1024.0;
    }
  return std::nullopt;
}

std::optional<double> file_number(const std::string& file) {
  std::ifstream in(file);
  double v = 0.0;
  if (in >> v) return v;
  return std::nullopt;  // absent, or "max" (no limit)
}

/// memory.max − memory.current of this process's cgroup (v2), if it sets a limit.
std::optional<double> cgroup_headroom() {
  std::ifstream in("/proc/self/cgroup");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("0::", 0) == 0) {
      const std::string dir = "/sys/fs/cgroup" + line.substr(3);
      const auto max = file_number(dir + "/memory.max"), used = file_number(dir + "/memory.current");
      if (max && used) return *max > *used ? *max - *used : 0.0;
    }
  return std::nullopt;
}

/// RLIMIT_AS less the address space mapped now (VmSize), if a limit is set.
std::optional<double> address_space_headroom() {
  rlimit rl{};
  if (getrlimit(RLIMIT_AS, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY) return std::nullopt;
  const double mapped = proc_kib("/proc/self/status", "VmSize").value_or(0.0);
  return double(rl.rlim_cur) > mapped ? double(rl.rlim_cur) - mapped : 0.0;
}

}  // namespace

std::optional<AvailableMemory> available_memory() {
  std::optional<AvailableMemory> least;
  const auto take = [&](std::optional<double> bytes, const char* source) {
    if (bytes && (!least || *bytes < least->bytes)) least = AvailableMemory{*bytes, source};
  };
  take(proc_kib("/proc/meminfo", "MemAvailable"), "MemAvailable in /proc/meminfo");
  take(cgroup_headroom(), "the cgroup's memory.max less its usage");
  take(address_space_headroom(), "the address-space limit (ulimit -v) less what is mapped");
  return least;
}

}  // namespace silodem
