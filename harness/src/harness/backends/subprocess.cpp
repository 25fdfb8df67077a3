#include "harness/backends/subprocess.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "silodem/core/interrupt.hpp"

namespace harness {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    const std::filesystem::path f = std::filesystem::path(dir) / name;
    if (::access(f.c_str(), X_OK) == 0) return f.string();
  }
  return "";
}

namespace {

/// Ends the child's whole process group: SIGTERM, then SIGKILL if it is still there after 5 s.
void end_group(pid_t pid) {
  ::kill(-pid, SIGTERM);
  for (int i = 0; i < 250; ++i) {
    if (::waitpid(pid, nullptr, WNOHANG) == pid) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(-pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
}

}  // namespace

ProcessOutcome run_process(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                           const std::filesystem::path& workdir, const std::filesystem::path& log,
                           double time_limit_s) {
  std::string cmd = "cd " + shell_quote(workdir.string()) + " && exec env";
  for (const auto& e : env) cmd += " " + shell_quote(e);
  cmd += " timeout --kill-after=5 " + std::to_string(int(std::ceil(time_limit_s)));
  for (const auto& a : argv) cmd += " " + shell_quote(a);
  cmd += " > " + shell_quote(log.string()) + " 2>&1 < /dev/null";
  const auto start = std::chrono::steady_clock::now();
  // Its own process group, so that a stop signal to silodem ends the code and all it started.
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("cannot start ") + argv.at(0) + ": " + std::strerror(errno));
  if (pid == 0) {
    ::setpgid(0, 0);
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  int s = 0;
  while (::waitpid(pid, &s, WNOHANG) != pid) {
    if (const int sig = silodem::stop_signal()) {
      end_group(pid);
      throw silodem::Interrupted(sig, "interrupted by " + silodem::signal_name(sig) + " while " + argv.at(0) +
                                          " ran in " + workdir.string() + " (ended; its partial directory is left)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ProcessOutcome o;
  o.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.exit_status = WIFEXITED(s) ? WEXITSTATUS(s) : 128 + (WIFSIGNALED(s) ? WTERMSIG(s) : 0);
  return o;
}

std::string tail(const std::filesystem::path& file, int lines) {
  std::ifstream in(file);
  std::deque<std::string> last;
  std::string l;
  while (std::getline(in, l)) {
    last.push_back(l);
    if (int(last.size()) > lines) last.pop_front();
  }
  std::string out;
  for (const auto& x : last) out += x + "\n";
  return out;
}

}  // namespace harness
