#include "silodem/checkpoint/checkpoint_file.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "silodem/output/result_dir.hpp"

namespace silodem {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'S', 'I', 'L', 'O', 'D', 'E', 'M', 'C'};
// magic, format, reserved, fingerprint, step, payload length; then the payload; then the CRC.
constexpr std::size_t kHeader = 8 + 4 + 4 + 8 + 8 + 8;

std::uint32_t crc(const char* data, std::size_t n) {
  uLong c = crc32(0L, Z_NULL, 0);
  // zlib takes uInt lengths: feed large payloads in pieces.
  while (n > 0) {
    const uInt piece = uInt(std::min<std::size_t>(n, 1u << 30));
    c = crc32(c, reinterpret_cast<const Bytef*>(data), piece);
    data += piece;
    n -= piece;
  }
  return std::uint32_t(c);
}

template <class T>
void put(std::string& s, T v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T>
T get(const std::string& s, std::size_t at) {
  T v;
  std::memcpy(&v, s.data() + at, sizeof v);
  return v;
}

void write_all(int fd, const std::string& bytes, const fs::path& file) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t w = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) throw CheckpointError("cannot write checkpoint " + file.string() + ": " + std::strerror(errno));
    done += std::size_t(w);
  }
}

long step_of(const fs::path& f) {
  const std::string n = f.filename().string();  // step-<N>.ckpt
  if (n.rfind("step-", 0) != 0 || f.extension() != ".ckpt") return -1;
  try {
    return std::stol(n.substr(5, n.size() - 10));
  } catch (...) {
    return -1;
  }
}

}  // namespace

std::string encode_checkpoint(std::uint64_t fingerprint, long step, const std::string& payload) {
  std::string s(kMagic, sizeof kMagic);
  put<std::uint32_t>(s, kCheckpointFormat);
  put<std::uint32_t>(s, 0);
  put<std::uint64_t>(s, fingerprint);
  put<std::int64_t>(s, step);
  put<std::uint64_t>(s, payload.size());
  s += payload;
  put<std::uint32_t>(s, crc(s.data(), s.size()));
  return s;
}

std::string decode_checkpoint(const std::string& bytes, std::uint64_t fingerprint, long* step) {
  if (bytes.size() < kHeader + 4 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw CheckpointError("not a silodem checkpoint (no header)");
  if (const auto v = get<std::uint32_t>(bytes, 8); v != kCheckpointFormat)
    throw CheckpointError("checkpoint format " + std::to_string(v) + ", this build reads format " +
                          std::to_string(kCheckpointFormat));
  const auto n = get<std::uint64_t>(bytes, 32);
  if (n != bytes.size() - kHeader - 4)
    throw CheckpointError("checkpoint is truncated or padded: header says " + std::to_string(n) + " payload bytes, file has " +
                          std::to_string(bytes.size() - kHeader - 4));
  if (crc(bytes.data(), bytes.size() - 4) != get<std::uint32_t>(bytes, bytes.size() - 4))
    throw CheckpointError("checkpoint checksum mismatch (the file is damaged)");
  if (const auto fp = get<std::uint64_t>(bytes, 16); fingerprint != 0 && fp != fingerprint)
    throw CheckpointError("checkpoint belongs to another case (or the case file changed since it was written)");
  if (step) *step = long(get<std::int64_t>(bytes, 24));
  return bytes.substr(kHeader, n);
}

std::uint64_t case_fingerprint(const std::string& text) {
  const std::uint64_t f = std::uint64_t(text.size()) << 32 | crc(text.data(), text.size());
  return f != 0 ? f : 1;  // 0 means "any case"
}

void resume_file(const fs::path& file, std::uintmax_t bytes) {
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  if (ec) throw CheckpointError("cannot restart: " + file.string() + " is missing (" + ec.message() + ")");
  if (size < bytes)
    throw CheckpointError("cannot restart: " + file.string() + " holds " + std::to_string(size) +
                          " bytes, fewer than the " + std::to_string(bytes) + " the checkpoint recorded");
  fs::resize_file(file, bytes);
}

void CheckpointStore::save(std::uint64_t fingerprint, long step, const std::string& payload) const {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw CheckpointError("cannot create " + dir_.string() + ": " + ec.message());
  if (!read_marker(dir_)) write_marker(dir_, "checkpoints", "checkpoints");
  const fs::path final_file = dir_ / ("step-" + std::to_string(step) + ".ckpt");
  const fs::path tmp = dir_ / ("step-" + std::to_string(step) + ".ckpt.tmp");
  const std::string bytes = encode_checkpoint(fingerprint, step, payload);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw CheckpointError("cannot create checkpoint " + tmp.string() + ": " + std::strerror(errno));
  try {
    write_all(fd, bytes, tmp);
    if (::fsync(fd) != 0) throw CheckpointError("cannot fsync checkpoint " + tmp.string() + ": " + std::strerror(errno));
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) throw CheckpointError("cannot close checkpoint " + tmp.string() + ": " + std::strerror(errno));
  fs::rename(tmp, final_file, ec);
  if (ec) throw CheckpointError("cannot rename checkpoint " + tmp.string() + ": " + ec.message());
  if (const int dfd = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
    ::fsync(dfd);  // the rename itself survives a crash only once the directory is on disk
    ::close(dfd);
  }
  const auto all = files();
  for (std::size_t i = std::size_t(std::max(keep_, 1)); i < all.size(); ++i) fs::remove(all[i]);
}

std::vector<fs::path> CheckpointStore::files() const {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir_)) return out;
  for (const auto& e : fs::directory_iterator(dir_))
    if (step_of(e.path()) >= 0) out.push_back(e.path());
  std::sort(out.begin(), out.end(), [](const fs::path& a, const fs::path& b) { return step_of(a) > step_of(b); });
  return out;
}

CheckpointStore::Loaded CheckpointStore::newest_valid(std::uint64_t fingerprint) const {
  Loaded out;
  for (const auto& f : files()) {
    try {
      std::ifstream in(f, std::ios::binary);
      std::ostringstream s;
      s << in.rdbuf();
      out.payload = decode_checkpoint(s.str(), fingerprint, &out.step);
      out.file = f;
      return out;
    } catch (const CheckpointError& e) {
      out.refused.push_back(f.string() + ": " + e.what());
    }
  }
  std::string why = "no usable checkpoint in " + dir_.string();
  if (out.refused.empty()) why += " (none written: the run stopped before its first checkpoint)";
  for (const auto& r : out.refused) why += "\n  " + r;
  throw CheckpointError(why);
}

}  // namespace silodem
