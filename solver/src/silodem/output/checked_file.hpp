#pragma once
// An output file whose every write, flush and close is checked: the first failure throws
// WriteError naming the file and the system's reason (errno), so a full disk or a name too long
// never leaves a result that looks complete. Buffered in memory, written in large pieces.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "silodem/output/write_error.hpp"

namespace silodem {

class CheckedFile {
 public:
  /// Creates (truncates) `file`, or with `append` opens it for appending.
  explicit CheckedFile(std::filesystem::path file, bool append = false);
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;
  /// Closes without throwing if close() was not called (an error path is already unwinding).
  ~CheckedFile();

  void write(std::string_view text);
  /// Flushes to the operating system; returns the file's size (what a checkpoint records).
  std::uintmax_t flush();
  /// Flushes and closes; throws if either fails (NFS and some full disks report only here).
  void close();
  const std::filesystem::path& path() const { return file_; }

 private:
  [[noreturn]] void fail(const char* what) const;
  std::filesystem::path file_;
  std::FILE* f_ = nullptr;
};

/// Writes `text` as the whole content of `file`, checked, through a temporary sibling renamed
/// into place: a reader never sees a half-written file.
void write_file_checked(const std::filesystem::path& file, std::string_view text);

/// The same for content written piece by piece: `write` fills the temporary file (and may throw,
/// which removes it), then it is closed and renamed into place.
void write_file_atomically(const std::filesystem::path& file, const std::function<void(CheckedFile&)>& write);

}  // namespace silodem
