#include "silodem/output/manifest.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <nlohmann/json.hpp>

#include "silodem/output/checked_file.hpp"
#include "silodem/output/result_dir.hpp"

namespace silodem {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Entry {
  std::uintmax_t bytes = 0;
  std::string crc32;  // 8 hex digits
};

/// A CRC-32 as 8 hex digits.
std::string hex8(uLong crc) {
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08lx", crc & 0xffffffffUL);
  return hex;
}

/// Size and CRC-32 of a file as it is on disk; nothing if it cannot be read.
bool measure(const fs::path& file, Entry& e) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::vector<char> buf(1 << 20);
  uLong c = crc32(0L, Z_NULL, 0);
  e.bytes = 0;
  while (in) {
    in.read(buf.data(), std::streamsize(buf.size()));
    const std::streamsize n = in.gcount();
    if (n <= 0) break;
    c = crc32(c, reinterpret_cast<const Bytef*>(buf.data()), uInt(n));
    e.bytes += std::uintmax_t(n);
  }
  if (in.bad()) return false;
  e.crc32 = hex8(c);
  return true;
}

/// Every regular file under `dir` (relative paths, sorted), the marker and the manifest aside.
std::vector<std::string> listed_files(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& de : fs::recursive_directory_iterator(dir)) {
    if (!de.is_regular_file()) continue;
    const std::string rel = fs::relative(de.path(), dir).generic_string();
    if (rel == kMarkerName || rel == kManifestName) continue;
    files.push_back(rel);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

void write_manifest(const fs::path& dir) {
  json files = json::array();
  for (const std::string& rel : listed_files(dir)) {
    Entry e;
    if (!measure(dir / rel, e)) throw WriteError(dir / rel, "cannot read it back for the manifest");
    files.push_back({{"path", rel}, {"bytes", e.bytes}, {"crc32", e.crc32}});
  }
  write_file_checked(dir / kManifestName,
                     json{{"format", "silodem-manifest/1"}, {"files", std::move(files)}}.dump(1) + "\n");
}

std::vector<std::string> verify_manifest(const fs::path& dir) {
  std::vector<std::string> problems;
  std::ifstream in(dir / kManifestName);
  if (!in) return {"no " + std::string(kManifestName) + ": the result was never finished"};
  json m;
  try {
    m = json::parse(in);
  } catch (const json::exception& e) {
    return {std::string(kManifestName) + " is not valid JSON: " + e.what()};
  }
  if (!m.is_object() || m.value("format", "") != "silodem-manifest/1" || !m.contains("files") || !m["files"].is_array())
    return {std::string(kManifestName) + " is not a silodem manifest (format silodem-manifest/1)"};
  std::map<std::string, Entry> listed;
  for (const auto& f : m["files"]) {
    if (!f.is_object() || !f.contains("path") || !f["path"].is_string() || !f.contains("bytes") ||
        !f["bytes"].is_number_unsigned() || !f.contains("crc32") || !f["crc32"].is_string())
      return {std::string(kManifestName) + ": an entry without path, bytes and crc32"};
    listed[f["path"].get<std::string>()] = {f["bytes"].get<std::uintmax_t>(), f["crc32"].get<std::string>()};
  }
  for (const auto& [rel, want] : listed) {
    Entry got;
    if (!measure(dir / rel, got)) problems.push_back(rel + ": listed in the manifest but missing or unreadable");
    else if (got.bytes != want.bytes)
      problems.push_back(rel + ": " + std::to_string(got.bytes) + " bytes, the manifest says " + std::to_string(want.bytes));
    else if (got.crc32 != want.crc32)
      problems.push_back(rel + ": CRC-32 " + got.crc32 + ", the manifest says " + want.crc32);
  }
  for (const std::string& rel : listed_files(dir))
    if (!listed.count(rel)) problems.push_back(rel + ": not listed in the manifest");
  return problems;
}

std::string text_digest(const std::string& text) {
  uLong c = crc32(0L, Z_NULL, 0);
  for (std::size_t at = 0; at < text.size(); at += 1 << 20) {  // uInt lengths
    const std::size_t n = std::min<std::size_t>(text.size() - at, 1 << 20);
    c = crc32(c, reinterpret_cast<const Bytef*>(text.data() + at), uInt(n));
  }
  return std::to_string(text.size()) + ":" + hex8(c);
}

std::string file_digest(const fs::path& file) {
  Entry e;
  if (!measure(file, e)) throw std::runtime_error(file.string() + ": cannot be read");
  return std::to_string(e.bytes) + ":" + e.crc32;
}

}  // namespace silodem
