#include "silodem/output/result_dir.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>

#include "silodem/output/checked_file.hpp"
#include "silodem/output/manifest.hpp"
#include "silodem/run/simulation.hpp"

namespace silodem {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string g_command = "silodem";

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return b;
}

/// Absolute, with symlinks and "." / ".." resolved as far as the path exists.
fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

bool is_same_or_ancestor(const fs::path& a, const fs::path& b) {
  auto ia = a.begin(), ib = b.begin();
  for (; ia != a.end(); ++ia, ++ib) {
    if (ia->empty()) continue;  // a trailing separator
    if (ib == b.end() || *ia != *ib) return false;
  }
  return true;
}

/// Refuses a path that is the working directory, an ancestor of it, or is or holds an input.
void check_not_precious(const fs::path& p, const fs::path& given, const std::vector<fs::path>& inputs,
                        const std::string& option) {
  std::error_code ec;
  const fs::path cwd = resolved(fs::current_path(ec));
  if (p == cwd) throw OutputPathError(given, option + " names the working directory");
  if (is_same_or_ancestor(p, cwd)) throw OutputPathError(given, option + " names an ancestor of the working directory");
  for (const auto& in : inputs) {
    const fs::path r = resolved(in);
    if (p == r) throw OutputPathError(given, option + " names the input " + in.string());
    if (is_same_or_ancestor(p, r)) throw OutputPathError(given, option + " names a directory that holds the input " + in.string());
  }
}

bool alive(long pid) { return ::kill(pid_t(pid), 0) == 0 || errno == EPERM; }

}  // namespace

void set_command_line(int argc, char** argv) {
  g_command.clear();
  for (int i = 0; i < argc; ++i) g_command += (i ? " " : "") + std::string(argv[i]);
}

void write_marker(const fs::path& dir, const std::string& kind, const std::string& state) {
  const json m = {{"format", "silodem-marker/1"}, {"version", silodem_version()}, {"kind", kind},
                  {"state", state}, {"command", g_command}, {"pid", long(::getpid())}, {"written", utc_now()}};
  write_file_checked(dir / kMarkerName, m.dump(1) + "\n");
}

std::optional<Marker> read_marker(const fs::path& dir) {
  std::ifstream in(dir / kMarkerName);
  if (!in) return std::nullopt;
  try {
    const json m = json::parse(in);
    if (!m.is_object() || m.value("format", "") != "silodem-marker/1") return std::nullopt;
    return Marker{m.value("kind", ""), m.value("state", ""), m.value("command", ""), m.value("pid", 0L),
                  m.value("written", "")};
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

void check_output_dir(const fs::path& dir, const std::vector<fs::path>& inputs, const std::string& option) {
  if (dir.empty()) throw OutputPathError(dir, option + " is empty");
  const fs::path p = resolved(dir);
  check_not_precious(p, dir, inputs, option);
  std::error_code ec;
  const auto st = fs::status(p, ec);
  if (!fs::exists(st)) return;
  if (!fs::is_directory(st)) throw OutputPathError(dir, option + " names an existing file, not a result directory");
  if (!read_marker(p))
    throw OutputPathError(dir, option + " names an existing directory that silodem did not write (it has no " +
                                   kMarkerName + "); silodem replaces only its own results: choose another path "
                                   "or remove it yourself");
}

std::string report_marker_line() {
  return "<!-- written by silodem (silodem-report/1); the next run with this --report replaces it -->";
}

void check_output_file(const fs::path& file, const std::vector<fs::path>& inputs, const std::string& option) {
  if (file.empty() || !file.has_filename()) throw OutputPathError(file, option + " needs a file name");
  const fs::path p = resolved(file);
  check_not_precious(p, file, inputs, option);
  std::error_code ec;
  const auto st = fs::status(p, ec);
  if (!fs::exists(st)) return;
  if (fs::is_directory(st)) throw OutputPathError(file, option + " names a directory, not a file");
  std::ifstream in(p);
  std::string first;
  std::getline(in, first);
  if (first != report_marker_line())
    throw OutputPathError(file, option + " names an existing file that silodem did not write (its first line is not "
                                         "silodem's report marker); choose another path or remove it yourself");
}

void make_root(const fs::path& dir) {
  if (const auto m = read_marker(dir)) {
    if (m->kind != "root")
      throw OutputPathError(dir, "is a result directory of kind \"" + m->kind + "\", not a verify or compare root");
    return;
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw WriteError(dir, "cannot create the directory: " + ec.message());
  write_marker(dir, "root", "root");
}

void remove_marked(const fs::path& dir) {
  std::error_code ec;
  const auto st = fs::symlink_status(dir, ec);
  if (!fs::exists(st)) return;
  if (fs::is_symlink(st)) {
    fs::remove(dir, ec);  // the link, never what it points to
  } else {
    if (!fs::is_directory(st) || !read_marker(dir))
      throw OutputPathError(dir, "is not a directory silodem wrote (no " + std::string(kMarkerName) + "); left as it is");
    fs::remove_all(dir, ec);
  }
  if (ec) throw WriteError(dir, "cannot remove: " + ec.message());
}

std::vector<std::string> clean_stale_partials(const fs::path& out, const fs::path& keep) {
  std::vector<std::string> said;
  const fs::path abs = fs::absolute(out).lexically_normal();
  const fs::path parent = abs.parent_path();
  const std::string prefix = abs.filename().string() + ".partial-";
  std::error_code ec;
  if (!fs::is_directory(parent, ec)) return said;
  for (const auto& de : fs::directory_iterator(parent, ec)) {
    const std::string name = de.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(digits);
    if (pid == long(::getpid()) || (!keep.empty() && resolved(de.path()) == resolved(keep))) continue;
    if (alive(pid)) {
      said.push_back(de.path().string() + " belongs to process " + digits + ", still running: left alone");
    } else if (!read_marker(de.path())) {
      said.push_back(de.path().string() + " is not marked as silodem's: left alone");
    } else {
      fs::remove_all(de.path(), ec);
      said.push_back(ec ? de.path().string() + ": cannot remove (" + ec.message() + ")"
                        : "removed " + de.path().string() + ", left by process " + digits + ", which has ended");
    }
  }
  return said;
}

void publish(const fs::path& tmp, const fs::path& final_dir, const std::string& state) {
  const auto m = read_marker(tmp);
  write_manifest(tmp);
  write_marker(tmp, m ? m->kind : "run", state);
  remove_marked(final_dir);
  std::error_code ec;
  if (final_dir.has_parent_path()) fs::create_directories(final_dir.parent_path(), ec);
  if (ec) throw WriteError(final_dir.parent_path(), "cannot create the directory: " + ec.message());
  fs::rename(tmp, final_dir, ec);
  if (ec) throw WriteError(final_dir, "cannot rename " + tmp.string() + " into place: " + ec.message());
}

}  // namespace silodem
