#include "harness/backends/subprocess.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <sstream>

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

ProcessOutcome run_process(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                           const std::filesystem::path& workdir, const std::filesystem::path& log,
                           double time_limit_s) {
  std::string cmd = "cd " + shell_quote(workdir.string()) + " && env";
  for (const auto& e : env) cmd += " " + shell_quote(e);
  cmd += " timeout --kill-after=5 " + std::to_string(int(std::ceil(time_limit_s)));
  for (const auto& a : argv) cmd += " " + shell_quote(a);
  cmd += " > " + shell_quote(log.string()) + " 2>&1 < /dev/null";
  const auto start = std::chrono::steady_clock::now();
  const int s = std::system(cmd.c_str());
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
