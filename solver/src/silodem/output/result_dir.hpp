#pragma once
// Result directories and the marker that makes them silodem's. Every directory silodem writes
// (a run's results, a verify or compare root, checkpoints, a partial or failed run) carries
// DIR/.silodem-result.json: format, version, kind, state, the command and the pid that wrote it.
// silodem replaces or deletes a directory only if it carries that marker, and never one that is
// the working directory, one of its ancestors, or holds an input.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "silodem/output/write_error.hpp"

namespace silodem {

inline constexpr const char* kMarkerName = ".silodem-result.json";

struct Marker {
  std::string kind;   // "run", "reference-run", "root", "checkpoints"
  std::string state;  // "partial", "complete", "failed", "interrupted" (a root: "root")
  std::string command;
  long pid = 0;
  std::string written;  // UTC, ISO 8601
};

/// The command line recorded in every marker (main sets it once).
void set_command_line(int argc, char** argv);

void write_marker(const std::filesystem::path& dir, const std::string& kind, const std::string& state);
/// The marker of `dir`, or nothing if it has none (or one silodem cannot read as its own).
std::optional<Marker> read_marker(const std::filesystem::path& dir);

/// Refuses (OutputPathError) an output directory that silodem may not create or replace: an
/// existing file, an existing directory without the marker, the working directory or one of its
/// ancestors, or a directory that is or holds one of `inputs`. `option` names it in the message.
void check_output_dir(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& inputs,
                      const std::string& option);

/// The same rule for an output file (--report): it may replace only a file silodem wrote, whose
/// first line is `report_marker_line()`; never a directory or an input.
void check_output_file(const std::filesystem::path& file, const std::vector<std::filesystem::path>& inputs,
                       const std::string& option);
std::string report_marker_line();

/// A verify or compare root: created and marked if missing; checked by check_output_dir before.
void make_root(const std::filesystem::path& dir);

/// Deletes a directory silodem wrote (it carries the marker); a missing one is fine. Anything
/// else is refused with OutputPathError: this is the only way silodem deletes a directory.
void remove_marked(const std::filesystem::path& dir);

/// DIR.partial-<pid> beside `out` of processes no longer alive: removed when marked (their
/// names returned as messages), reported and left when not. `keep` is never touched (the
/// partial a restart resumes).
std::vector<std::string> clean_stale_partials(const std::filesystem::path& out, const std::filesystem::path& keep = {});

/// Finishes a result directory written in `tmp`: its manifest written last, its marker set to
/// `state`, then renamed to `final_dir` (an earlier marked result there is replaced).
void publish(const std::filesystem::path& tmp, const std::filesystem::path& final_dir, const std::string& state);

}  // namespace silodem
