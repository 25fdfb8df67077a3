// Output paths and writes as a user meets them (issue 26 §1-2): nothing silodem did not write is
// deleted or overwritten, whatever --out or --report names; a write that fails (full disk, name
// too long, no permission) stops the job with the file and the system's reason, exit 3, and no
// result directory; a result's manifest lets anyone check that it is complete.
#include <gtest/gtest.h>

#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "harness/result_files.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Outcome {
  int code = -1;
  std::string out;  // stdout and stderr together
};

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs the binary in `cwd` with `args` (a shell fragment), optionally as another user.
Outcome run_in(const fs::path& cwd, const std::string& args, const std::string& prefix = "") {
  const fs::path log = fs::temp_directory_path() / ("silodem_safety_" + std::to_string(::getpid()) + ".log");
  const std::string cmd = "cd '" + cwd.string() + "' && " + prefix + std::string(SILODEM_BINARY) + " " + args +
                          " >'" + log.string() + "' 2>&1";
  const int s = std::system(cmd.c_str());
  Outcome o{WIFEXITED(s) ? WEXITSTATUS(s) : -1, slurp(log)};
  fs::remove(log);
  return o;
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("silodem_safety_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

/// Every file and folder under `root` with its content: the sentinel a refused command must leave.
std::map<std::string, std::string> tree(const fs::path& root) {
  std::map<std::string, std::string> t;
  for (const auto& e : fs::recursive_directory_iterator(root))
    t[fs::relative(e.path(), root).string()] = e.is_directory() ? "<dir>" : slurp(e.path());
  return t;
}

/// Two balls, 5,000 steps and a series row every step (about 700 KB of series.csv).
const std::string kCase = R"({"name": "safety", "gravity": [0, 0, -9.81],
  "materials": {"g": {"density": 2500, "stiffness": 2e5, "damping": 6}},
  "balls": [{"id": "a", "material": "g", "radius": 0.005, "position": [0, 0, 0.0099998716005]},
            {"id": "w", "material": "g", "radius": 0.005, "position": [0, 0, 0], "fixed": true}],
  "time": {"dt": 1e-5, "duration": 0.05}})";

/// A working directory with things a user keeps: the case, notes, a data folder, a sibling folder.
fs::path user_tree(const std::string& name) {
  const fs::path d = scratch(name);
  fs::create_directories(d / "work" / "sub");
  fs::create_directories(d / "work" / "cases");
  fs::create_directories(d / "sibling");
  std::ofstream(d / "work" / "case.json") << [] {
    json c = json::parse(kCase);
    c["verify"] = {{"checks", {{{"type", "energy_balance"}, {"tolerance", 0.01}}}}};
    return c.dump();
  }();
  std::ofstream(d / "work" / "cases" / "case2.json") << kCase;
  std::ofstream(d / "work" / "notes.txt") << "a user's notes\n";
  std::ofstream(d / "work" / "sub" / "data.txt") << "a user's data\n";
  std::ofstream(d / "sibling" / "keep.txt") << "keep\n";
  return d;
}

/// The pid of a process that has just ended (for a stale DIR.partial-<pid>).
long dead_pid() {
  const pid_t p = fork();
  if (p == 0) _exit(0);
  waitpid(p, nullptr, 0);
  return long(p);
}

/// A small tmpfs mounted for the test (root only): a real filesystem that runs out of room.
class FullDisk {
 public:
  FullDisk(const fs::path& at, const char* size) : at_(at) {
    fs::create_directories(at_);
    mounted_ = geteuid() == 0 && ::mount("tmpfs", at_.c_str(), "tmpfs", 0, (std::string("size=") + size).c_str()) == 0;
  }
  ~FullDisk() {
    if (mounted_) ::umount(at_.c_str());
  }
  bool mounted() const { return mounted_; }

 private:
  fs::path at_;
  bool mounted_ = false;
};

}  // namespace

TEST(OutputSafety, EveryRefusedOutputPathExitsTwoNamesItAndLeavesTheTreeAsItWas) {
  const fs::path d = user_tree("refused");
  const fs::path w = d / "work";
  std::ofstream(w / "existing_file.txt") << "not a result\n";
  std::ofstream(w / "mine.md") << "# my own report\n";
  fs::create_directories(w / "res.failed");  // a folder the user made, in the way of a failed run
  const auto before = tree(d);
  const struct {
    std::string args, reason;
  } refused[] = {
      {"run case.json --out .", "working directory"},
      {"run case.json --out " + w.string(), "working directory"},
      {"run case.json --out ..", "ancestor of the working directory"},
      {"run case.json --out /", "ancestor of the working directory"},
      {"run case.json --out ../sibling", "silodem did not write"},
      {"run case.json --out sub", "silodem did not write"},
      {"run case.json --out existing_file.txt", "existing file"},
      {"run case.json --out case.json", "input"},
      {"run cases/case2.json --out cases", "holds the input"},
      {"run case.json --out res", "silodem did not write"},  // res.failed is not silodem's
      {"verify case.json --out .", "working directory"},
      {"verify case.json --out ../sibling", "silodem did not write"},
      {"verify case.json --out v --report mine.md", "silodem did not write"},
      {"verify case.json --out v --report sub", "directory"},
      {"verify case.json --out v --report case.json", "input"},
      {"compare case.json --codes silodem --out ..", "ancestor"},
      {"compare cases/case2.json --codes silodem --out cases", "holds the input"},
  };
  for (const auto& r : refused) {
    const Outcome o = run_in(w, r.args + " --quiet");
    EXPECT_EQ(o.code, 2) << r.args << "\n" << o.out;
    EXPECT_NE(o.out.find("refused output path"), std::string::npos) << r.args << "\n" << o.out;
    EXPECT_NE(o.out.find(r.reason), std::string::npos) << r.args << "\n" << o.out;
    EXPECT_EQ(tree(d), before) << r.args << " changed the user's files";
  }
  fs::remove_all(d);
}

TEST(OutputSafety, ARunReplacesOnlyItsOwnMarkedResultsAndTheManifestVerifiesThem) {
  const fs::path d = user_tree("marked");
  const fs::path w = d / "work";
  ASSERT_EQ(run_in(w, "run case.json --out res --quiet").code, 0);
  const json marker = json::parse(slurp(w / "res" / ".silodem-result.json"));
  EXPECT_EQ(marker["format"], "silodem-marker/1");
  EXPECT_EQ(marker["state"], "complete");
  EXPECT_NE(marker["command"].get<std::string>().find("run case.json --out res"), std::string::npos);
  // The second run replaces the first (it is silodem's); check verifies it.
  ASSERT_EQ(run_in(w, "run case.json --out res --quiet").code, 0);
  Outcome c = run_in(w, "check res");
  EXPECT_EQ(c.code, 0) << c.out;
  EXPECT_NE(c.out.find("complete and intact"), std::string::npos) << c.out;
  EXPECT_NO_THROW(harness::read_result(w / "res"));

  // One byte changed, a file added, a file removed: each found, named, and the harness reads none of it.
  const json manifest = json::parse(slurp(w / "res" / "manifest.json"));
  EXPECT_GE(manifest["files"].size(), 3u);  // series.csv, state.json, summary.json at least
  std::string series = slurp(w / "res" / "series.csv");
  series[series.size() / 2] = series[series.size() / 2] == '1' ? '2' : '1';
  std::ofstream(w / "res" / "series.csv", std::ios::binary) << series;
  c = run_in(w, "check res");
  EXPECT_EQ(c.code, 1) << c.out;
  EXPECT_NE(c.out.find("series.csv: CRC-32"), std::string::npos) << c.out;
  EXPECT_THROW(harness::read_result(w / "res"), std::runtime_error);
  std::ofstream(w / "res" / "extra.txt") << "x";
  EXPECT_NE(run_in(w, "check res").out.find("extra.txt: not listed"), std::string::npos);
  fs::remove(w / "res" / "state.json");
  EXPECT_NE(run_in(w, "check res").out.find("state.json: listed in the manifest but missing"), std::string::npos);
  fs::remove(w / "res" / "manifest.json");
  EXPECT_NE(run_in(w, "check res").out.find("never finished"), std::string::npos);
  // Not a result directory at all (no marker): neither a case file, bad input.
  c = run_in(w, "check sub");
  EXPECT_EQ(c.code, 2) << c.out;
  EXPECT_NE(c.out.find("is a directory, not a case file"), std::string::npos) << c.out;
  fs::remove_all(d);
}

TEST(OutputSafety, StalePartialsOfEndedProcessesAreRemovedOnlyWhenMarkedAndAStaleFailedGoes) {
  const fs::path d = user_tree("stale");
  const fs::path w = d / "work";
  const long pid = dead_pid();
  const fs::path marked = w / ("res.partial-" + std::to_string(pid));
  const fs::path unmarked = w / ("res.partial-" + std::to_string(dead_pid()));
  fs::create_directories(marked);
  fs::create_directories(unmarked);
  std::ofstream(marked / ".silodem-result.json")
      << json{{"format", "silodem-marker/1"}, {"kind", "run"}, {"state", "partial"}, {"pid", pid}}.dump();
  std::ofstream(unmarked / "data.txt") << "someone else's\n";

  // A run that fails (its step limit) leaves res.failed; the message names it.
  std::ofstream(w / "limited.json") << [] {
    json c = json::parse(kCase);
    c["guards"] = {{"max_steps", 10}};
    return c.dump();
  }();
  Outcome o = run_in(w, "run limited.json --out res --quiet");
  EXPECT_EQ(o.code, 3) << o.out;
  EXPECT_TRUE(fs::exists(w / "res.failed" / "summary.json"));
  EXPECT_EQ(json::parse(slurp(w / "res.failed" / ".silodem-result.json"))["state"], "failed");
  EXPECT_FALSE(fs::exists(w / "res"));
  EXPECT_NE(o.out.find("removed " + marked.string()), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(unmarked.string() + " is not marked"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(marked));
  EXPECT_EQ(slurp(unmarked / "data.txt"), "someone else's\n");

  // A good run: res is current, the older res.failed is gone. A failed one after it says that
  // res still holds the earlier result.
  ASSERT_EQ(run_in(w, "run case.json --out res --quiet").code, 0);
  EXPECT_FALSE(fs::exists(w / "res.failed"));
  o = run_in(w, "run limited.json --out res --quiet");
  EXPECT_EQ(o.code, 3);
  EXPECT_NE(o.out.find("still holds an earlier complete result"), std::string::npos) << o.out;
  EXPECT_EQ(json::parse(slurp(w / "res" / ".silodem-result.json"))["state"], "complete");
  fs::remove_all(d);
}

TEST(OutputSafety, AFullDiskStopsTheRunWithExitThreeNamingTheFileAndLeavesNoResult) {
  const fs::path d = user_tree("full");
  FullDisk disk(d / "full", "64k");
  if (!disk.mounted()) GTEST_SKIP() << "mounting a 64 KiB tmpfs needs root (this is uid " << geteuid() << ")";
  const fs::path w = d / "work";
  const Outcome o = run_in(w, "run case.json --out " + (d / "full" / "res").string() + " --quiet");
  EXPECT_EQ(o.code, 3) << o.out;
  EXPECT_NE(o.out.find("No space left on device"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("series.csv"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("no result directory was created"), std::string::npos) << o.out;
  EXPECT_TRUE(fs::is_empty(d / "full")) << "neither DIR nor its partial may stay on the full disk";

  // The report: verify writes its verdicts elsewhere, the report onto the full disk.
  {
    std::ofstream filler(d / "full" / "filler", std::ios::binary);
    const std::string block(4096, 'x');
    while (filler << block && filler.flush()) {
    }
  }
  const Outcome r = run_in(w, "verify case.json --out v --report " + (d / "full" / "report.md").string() + " --quiet");
  EXPECT_EQ(r.code, 3) << r.out;
  EXPECT_NE(r.out.find("report.md"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("No space left on device"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(d / "full" / "report.md"));
  fs::remove_all(d / "full" / "filler");
}

TEST(OutputSafety, ANameTooLongAndAFolderWithoutPermissionStopWithTheSystemsReason) {
  const fs::path d = user_tree("names");
  const fs::path w = d / "work";
  // 250 characters: DIR itself fits a file name (255), DIR.partial-<pid> does not.
  const std::string long_name(250, 'a');
  Outcome o = run_in(w, "run case.json --out " + long_name + " --quiet");
  EXPECT_EQ(o.code, 3) << o.out;
  EXPECT_NE(o.out.find("File name too long"), std::string::npos) << o.out;
  EXPECT_EQ(tree(w).size(), 6u) << "only the user's files";  // case.json, cases, cases/case2.json, notes, sub, sub/data

  // A folder the user may not write into. Root writes anywhere, so the run drops to nobody then.
  fs::create_directories(d / "locked");
  fs::permissions(d / "locked", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                    fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  fs::permissions(d, fs::perms::all);  // nobody must reach the case file
  fs::permissions(w, fs::perms::all);
  const std::string as = geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  o = run_in(w, "run case.json --out " + (d / "locked" / "res").string() + " --quiet", as);
  EXPECT_EQ(o.code, 3) << o.out;
  EXPECT_NE(o.out.find("Permission denied"), std::string::npos) << o.out;
  EXPECT_TRUE(fs::is_empty(d / "locked"));
  fs::permissions(d / "locked", fs::perms::all);
  fs::remove_all(d);
}

TEST(OutputSafety, AReportIntoAMissingFolderIsWrittenWholeAndMarked) {
  const fs::path d = user_tree("report");
  const fs::path w = d / "work";
  const Outcome o = run_in(w, "verify case.json --out v --report new/folder/report.md --quiet");
  EXPECT_TRUE(o.code == 0 || o.code == 1) << o.out;  // its verdict is not what this test is about
  ASSERT_TRUE(fs::exists(w / "new" / "folder" / "report.md")) << o.out;
  EXPECT_EQ(slurp(w / "new" / "folder" / "report.md").rfind("<!-- written by silodem", 0), 0u);
  // Its second run replaces it (it is silodem's), as it replaces the marked root.
  const int again = run_in(w, "verify case.json --out v --report new/folder/report.md --quiet").code;
  EXPECT_TRUE(again == 0 || again == 1);
  EXPECT_EQ(json::parse(slurp(w / "v" / ".silodem-result.json"))["kind"], "root");
  fs::remove_all(d);
}
