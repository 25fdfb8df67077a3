#pragma once
// The manifest of a result directory, written last: every file in it (the marker and the manifest
// itself aside) with its size in bytes and CRC-32, read back from disk. A result whose manifest
// does not verify is not complete, whatever its summary says; the harness reads no other.
#include <filesystem>
#include <string>
#include <vector>

namespace silodem {

inline constexpr const char* kManifestName = "manifest.json";

void write_manifest(const std::filesystem::path& dir);

/// What is wrong with the directory against its manifest (empty: it verifies): a missing
/// manifest, a listed file missing, of another size or checksum, a file the manifest does not list.
std::vector<std::string> verify_manifest(const std::filesystem::path& dir);

/// "<bytes>:<CRC-32>" of a file as it is on disk, as the manifest lists it: what a resumed sweep
/// compares to tell an unchanged case file. Throws std::runtime_error if it cannot be read.
std::string file_digest(const std::filesystem::path& file);

/// The same "<bytes>:<CRC-32>" of a text held in memory.
std::string text_digest(const std::string& text);

}  // namespace silodem
