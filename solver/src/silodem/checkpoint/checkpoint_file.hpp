#pragma once
// Checkpoint files (issue 6): a payload (checkpoint/archive.hpp) in a container that says what it
// is and whether it is whole — magic, format version, the case's fingerprint, the step, the
// payload length, and a CRC-32 (zlib) over all of it. Written atomically: to a temporary file,
// fsync'ed, renamed into place, the directory fsync'ed; a run killed mid-write leaves the older
// checkpoints intact. The store keeps the newest two, so one damaged file still leaves a restart.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "silodem/checkpoint/archive.hpp"

namespace silodem {

inline constexpr std::uint32_t kCheckpointFormat = 2;  // 2: wall pressure probes keep their balls' placements

/// The container around `payload`, as bytes.
std::string encode_checkpoint(std::uint64_t fingerprint, long step, const std::string& payload);
/// The payload of a container; throws CheckpointError saying what is wrong (another format, another
/// case, truncated, checksum mismatch). `fingerprint` 0 accepts any case (tools, the fuzz target).
std::string decode_checkpoint(const std::string& bytes, std::uint64_t fingerprint, long* step = nullptr);

/// A result file a restart appends to: cut back to the `bytes` it held at the checkpoint. Throws
/// CheckpointError if it is missing or shorter (it does not belong to that checkpoint).
void resume_file(const std::filesystem::path& file, std::uintmax_t bytes);

/// Identifies a case for restarts: a checkpoint of another case (or the same file edited) is refused.
std::uint64_t case_fingerprint(const std::string& canonical_case_text);

/// A directory of checkpoints, `step-<N>.ckpt`, the newest `keep` of them kept.
class CheckpointStore {
 public:
  explicit CheckpointStore(std::filesystem::path dir, int keep = 2) : dir_(std::move(dir)), keep_(keep) {}
  const std::filesystem::path& dir() const { return dir_; }
  /// Writes atomically, then deletes all but the newest `keep`.
  void save(std::uint64_t fingerprint, long step, const std::string& payload) const;
  /// Checkpoint files, newest first (by step).
  std::vector<std::filesystem::path> files() const;
  struct Loaded {
    std::string payload;
    long step = 0;
    std::filesystem::path file;
    std::vector<std::string> refused;  // "FILE: reason" for each newer file that could not be used
  };
  /// The newest checkpoint that decodes; throws CheckpointError listing every refusal if none does.
  Loaded newest_valid(std::uint64_t fingerprint) const;

 private:
  std::filesystem::path dir_;
  int keep_;
};

}  // namespace silodem
