#include "harness/sweep/sweep_progress.hpp"

#include <cstdio>

namespace harness {

SweepProgress::SweepProgress(silodem::ProgressStyle style, std::size_t total) : line_("sweep", style), total_(total) {}

std::string SweepProgress::text(std::size_t ended, std::size_t failed, std::size_t running,
                                const std::string& now_running) const {
  const double elapsed = line_.elapsed();
  const double left = ended > 0 ? elapsed / double(ended) * double(total_ - ended) : INFINITY;
  char b[256];
  std::snprintf(b, sizeof b, "%zu/%zu jobs ended (%zu failed), %zu running | %s elapsed, %s left%s", ended, total_,
                failed, running, silodem::format_duration(elapsed).c_str(),
                ended == total_ ? "nothing" : silodem::format_duration(left).c_str(),
                now_running.empty() ? "" : " | now: ");
  return b + now_running;
}

void SweepProgress::update(std::size_t ended, std::size_t failed, std::size_t running, const std::string& now_running) {
  if (line_.due()) line_.print(text(ended, failed, running, now_running));
}

void SweepProgress::finish(std::size_t ended, std::size_t failed) {
  if (line_.on()) line_.print(text(ended, failed, 0, ""));
  line_.finish();
}

std::string job_title(const SweepJob& job) {
  const std::string what = job.kind == "verify" ? "run" : job.kind == "state" ? "shared state" : job.code + " " + job.kind;
  return what + " of " + job.case_name + (job.variant.empty() ? "" : " " + job.variant);
}

}  // namespace harness
