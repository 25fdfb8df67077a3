#pragma once
// The progress line on stderr (run, verify, compare): on a terminal one line redrawn in place
// twice a second; elsewhere (a log file, a pipe) nothing, unless a plain line every N seconds is
// asked for (--progress-every N), which a log keeps and `tail -f` shows.
#include <chrono>
#include <string>

namespace silodem {

enum class ProgressMode { Off, Redraw, Log };

struct ProgressStyle {
  ProgressMode mode = ProgressMode::Off;
  double every_seconds = 0.5;
};

/// `every_seconds` > 0: a plain line that often; 0: redrawn on a terminal, nothing otherwise.
ProgressStyle progress_style(double every_seconds);

/// "1h02m", "3m05s", "12s", "0.4s"; "?" for a time that is not finite.
std::string format_duration(double seconds);

class ProgressLine {
 public:
  ProgressLine(std::string label, ProgressStyle style);
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine() { finish(); }
  bool on() const { return style_.mode != ProgressMode::Off; }
  /// Whether a line is due (reads the clock; callers ask every so many steps).
  bool due() const;
  void print(const std::string& text);
  /// Ends a redrawn line, so that what follows starts on a line of its own.
  void finish();
  /// Seconds since construction.
  double elapsed() const;

 private:
  std::string label_;
  ProgressStyle style_;
  std::chrono::steady_clock::time_point start_, last_;
  bool open_ = false;  // a redrawn line awaits its newline
};

}  // namespace silodem
