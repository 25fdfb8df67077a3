#include "silodem/core/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace silodem {

ProgressStyle progress_style(double every_seconds) {
  if (every_seconds > 0.0) return {ProgressMode::Log, every_seconds};
  return {::isatty(STDERR_FILENO) ? ProgressMode::Redraw : ProgressMode::Off, 0.5};
}

std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0.0 || s > 1e12) return "?";
  char b[32];
  if (s < 10.0) std::snprintf(b, sizeof b, "%.1fs", s);
  else if (s < 60.0) std::snprintf(b, sizeof b, "%lds", long(s));
  else if (s < 3600.0) std::snprintf(b, sizeof b, "%ldm%02lds", long(s) / 60, long(s) % 60);
  else std::snprintf(b, sizeof b, "%ldh%02ldm", long(s) / 3600, long(s) % 3600 / 60);
  return b;
}

ProgressLine::ProgressLine(std::string label, ProgressStyle style)
    : label_(std::move(label)), style_(style), start_(std::chrono::steady_clock::now()), last_(start_) {}

bool ProgressLine::due() const {
  if (!on()) return false;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count() >= style_.every_seconds;
}

void ProgressLine::print(const std::string& text) {
  if (!on()) return;
  last_ = std::chrono::steady_clock::now();
  if (style_.mode == ProgressMode::Redraw) {
    std::fprintf(stderr, "\r\033[K[%s] %s", label_.c_str(), text.c_str());
    open_ = true;
  } else {
    std::fprintf(stderr, "[%s] %s\n", label_.c_str(), text.c_str());
  }
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (open_) std::fputc('\n', stderr);
  open_ = false;
}

double ProgressLine::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace silodem
