#include "silodem/output/checked_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace silodem {

namespace fs = std::filesystem;

CheckedFile::CheckedFile(fs::path file, bool append) : file_(std::move(file)) {
  f_ = std::fopen(file_.c_str(), append ? "ab" : "wb");
  if (!f_) fail("cannot open");
  static_cast<void>(std::setvbuf(f_, nullptr, _IOFBF, 1 << 16));
}

CheckedFile::~CheckedFile() {
  if (f_) static_cast<void>(std::fclose(f_));
}

void CheckedFile::fail(const char* what) const {
  throw WriteError(file_, std::string(what) + ": " + std::strerror(errno));
}

void CheckedFile::write(std::string_view text) {
  if (!f_) throw WriteError(file_, "written after close");
  if (!text.empty() && std::fwrite(text.data(), 1, text.size(), f_) != text.size()) fail("write failed");
}

std::uintmax_t CheckedFile::flush() {
  if (std::fflush(f_) != 0) fail("flush failed");
  const long at = std::ftell(f_);
  if (at < 0) fail("cannot tell the file's size");
  return std::uintmax_t(at);
}

void CheckedFile::close() {
  if (!f_) return;
  std::FILE* f = f_;
  f_ = nullptr;
  const bool flushed = std::fflush(f) == 0;
  const int flush_errno = errno;
  const bool closed = std::fclose(f) == 0;
  if (!flushed) errno = flush_errno;
  if (!flushed || !closed) fail("close failed");
}

void write_file_checked(const fs::path& file, std::string_view text) {
  write_file_atomically(file, [&](CheckedFile& out) { out.write(text); });
}

void write_file_atomically(const fs::path& file, const std::function<void(CheckedFile&)>& write) {
  const fs::path tmp = file.string() + ".tmp-" + std::to_string(::getpid());
  try {
    CheckedFile out(tmp);
    write(out);
    out.close();
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(tmp, ec);
    throw WriteError(file, "cannot rename into place: " + why);
  }
}

}  // namespace silodem
