#pragma once
// The whole sweep's progress line (core/progress.hpp): jobs ended of all, failed, running, the
// job running longest, and the time left at the pace so far (elapsed / ended × those left).
#include <string>

#include "harness/sweep/job_plan.hpp"
#include "silodem/core/progress.hpp"

namespace harness {

class SweepProgress {
 public:
  SweepProgress(silodem::ProgressStyle style, std::size_t total);
  /// Prints if a line is due; `running` names what runs now ("" for nothing to name).
  void update(std::size_t ended, std::size_t failed, std::size_t running, const std::string& now_running);
  void finish(std::size_t ended, std::size_t failed);

 private:
  std::string text(std::size_t ended, std::size_t failed, std::size_t running, const std::string& now_running) const;
  silodem::ProgressLine line_;
  std::size_t total_;
};

/// "verify run of <case> <variant>" or "<code> <kind> of <case> <variant>": what a job is, briefly.
std::string job_title(const SweepJob& job);

}  // namespace harness
