#include "silodem/case/case_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "silodem/case/case_error.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/case/text_position.hpp"
#include "silodem/core/available_memory.hpp"

namespace silodem {

namespace {

/// What a file that is not a regular file is, for the message.
const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string mib(unsigned long bytes) { return std::to_string(bytes >> 20) + " MiB"; }

/// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_case_text(const std::filesystem::path& file) {
  const std::string name = file.string();
  // Non-blocking, so that opening a FIFO returns at once (it is refused below, never read).
  const Descriptor d{::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (d.fd < 0) throw CaseError(name, std::string("cannot open the case file: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(d.fd, &st) != 0) throw CaseError(name, std::string("cannot examine the case file: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw CaseError(name, std::string("is ") + kind_of(st.st_mode) +
                              ", not a case file: silodem reads a case from a regular file only");

  const unsigned long limit = limits::kCaseFileBytes;
  std::string text;
  // A file that is larger is counted, not held: the message gives where it passes the limit.
  const bool fits = st.st_size >= 0 && static_cast<unsigned long>(st.st_size) <= limit;
  if (fits) {
    // Held whole, and parsed into more: a file larger than what this process may still take
    // cannot be read (an address-space limit, a cgroup, a full machine).
    const auto room = available_memory();
    if (room && double(st.st_size) > room->bytes)
      throw CaseError(name, "the case file is " + std::to_string(st.st_size) + " bytes, more than the " +
                                std::to_string(static_cast<unsigned long long>(room->bytes)) +
                                " bytes this process can still take (" + room->source + ")");
    text.reserve(std::size_t(st.st_size));
  }
  TextPosition at;
  unsigned long total = 0;
  char chunk[1 << 16];
  for (;;) {
    const ssize_t n = ::read(d.fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw CaseError(name, std::string("cannot read the case file: ") + std::strerror(errno));
    if (n == 0) break;
    if (total + std::size_t(n) > limit) {
      if (fits) at = position_in(text, text.size());  // it grew while being read
      at.advance(chunk, std::size_t(limit - total));  // to the first byte beyond the limit
      throw CaseError(name, at.describe() + " (byte " + std::to_string(limit + 1) + "): the case file is larger than " +
                                mib(limit) + ", the limit for a case file (10^6 listed balls take at most about 330 MB); "
                                "let walls and drops make large scenes");
    }
    total += std::size_t(n);
    if (fits) text.append(chunk, std::size_t(n));
    else at.advance(chunk, std::size_t(n));
  }
  return text;
}

}  // namespace silodem
