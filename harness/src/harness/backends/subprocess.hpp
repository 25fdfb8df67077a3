#pragma once
// Runs a reference code as a child process in a working directory, with a wall-clock limit
// (coreutils `timeout`), its output captured to a log file.
#include <filesystem>
#include <string>
#include <vector>

namespace harness {

struct ProcessOutcome {
  int exit_status = -1;     // 124: timed out (coreutils timeout)
  double wall_seconds = 0.0;
  bool timed_out() const { return exit_status == 124; }
};

/// `argv` is run in `workdir`; stdout and stderr go to `log`. Environment overrides as "K=V".
ProcessOutcome run_process(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                           const std::filesystem::path& workdir, const std::filesystem::path& log,
                           double time_limit_s);

/// The last `lines` lines of a text file.
std::string tail(const std::filesystem::path& file, int lines);

/// The full path of an executable on PATH, or "".
std::string find_on_path(const std::string& name);

/// A string quoted for /bin/sh.
std::string shell_quote(const std::string& s);

}  // namespace harness
