#pragma once
#include <filesystem>
#include <string>

#include "silodem/core/job_stop.hpp"

namespace silodem {

/// A result file could not be written (full disk, name too long, no permission, ...): the job
/// stops, no result directory is created, exit code 3. Names the file and the system's reason.
class WriteError : public JobStop {
 public:
  WriteError(const std::filesystem::path& file, const std::string& reason)
      : JobStop(3, "cannot write " + file.string() + ": " + reason) {}
};

/// An output path silodem may not use (it holds something silodem did not write, or an input):
/// refused before anything runs, exit code 2.
class OutputPathError : public JobStop {
 public:
  OutputPathError(const std::filesystem::path& path, const std::string& reason)
      : JobStop(2, "refused output path " + path.string() + ": " + reason) {}
};

}  // namespace silodem
