// Bounded resources and safe names, as a user meets them: the real binary on hostile input —
// deep nesting (under an address-space limit, so memory that grows faster than the input is a
// crash, not a slow pass), a file past the size limit, /dev/zero and a FIFO as the case file, a
// count no machine holds, names that would leave the result directory, and two cases of one name
// in one verify call. Each is refused with exit 2, a message that says where, and no output.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Outcome {
  bool exited = false;
  int code = -1;    // exit status when it exited
  int signal = 0;   // the signal that ended it otherwise
  std::string output;  // stdout and stderr
};

/// Runs the binary with `args`; `address_space` > 0 sets RLIMIT_AS in the child first. A child
/// that blocks is killed after 60 s (SIGALRM survives exec), so a hang fails the test.
Outcome run(const std::vector<std::string>& args, rlim_t address_space = 0) {
  const fs::path log = fs::temp_directory_path() / ("silodem_limits_cli_" + std::to_string(::getpid()) + ".log");
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    if (address_space > 0) {
      const rlimit rl{address_space, address_space};
      if (::setrlimit(RLIMIT_AS, &rl) != 0) ::_exit(120);
    }
    ::alarm(60);
    std::vector<char*> argv{const_cast<char*>(SILODEM_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(SILODEM_BINARY, argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  Outcome o;
  o.exited = WIFEXITED(status);
  o.code = o.exited ? WEXITSTATUS(status) : -1;
  o.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  o.output = ss.str();
  fs::remove(log);
  return o;
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("silodem_limits_cli_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

json read_json(const fs::path& f) {
  std::ifstream in(f);
  return json::parse(in);
}

void write(const fs::path& f, const std::string& text) { std::ofstream(f) << text; }

const std::string kGood = R"({"name": "limits", "gravity": [0, 0, -9.81],
  "materials": {"g": {"density": 2500, "stiffness": 2e5, "damping": 6}},
  "balls": [{"id": "a", "material": "g", "radius": 0.005, "position": [0, 0, 0.0099998716005]},
            {"id": "w", "material": "g", "radius": 0.005, "position": [0, 0, 0], "fixed": true}],
  "time": {"dt": 1e-5, "duration": 0.01},
  "output": {"probes": [{"type": "ball", "name": "bouncer", "balls": ["a"]}]}})";

const fs::path kCases = fs::path(SILODEM_SOURCE_DIR) / "cases";
#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer maps terabytes of shadow memory: no address-space limit can be set under it.
constexpr bool kAsan = true;
constexpr rlim_t kAddressSpace = 0;
#else
constexpr bool kAsan = false;
constexpr rlim_t kAddressSpace = rlim_t(512) << 20;  // 512 MiB
#endif
#define SKIP_UNDER_ASAN() \
  if (kAsan) GTEST_SKIP() << "AddressSanitizer build: an address-space limit cannot be set under it"

#define EXPECT_REFUSED(o, text)                                                        \
  do {                                                                                 \
    EXPECT_TRUE((o).exited) << "signal " << (o).signal << ": " << (o).output;          \
    EXPECT_EQ((o).code, 2) << (o).output;                                              \
    EXPECT_NE((o).output.find(text), std::string::npos) << "no \"" << (text) << "\" in: " << (o).output; \
  } while (0)

}  // namespace

TEST(CliLimits, FortyThousandLevelsUnderAnAddressSpaceLimitAreRefusedWithTheirPosition) {
  SKIP_UNDER_ASAN();
  const fs::path d = scratch("deep");
  // 80 KB: an object whose member "a" opens 40,000 arrays on line 2 (was: past 4 GiB, bad_alloc).
  write(d / "deep.json", "{\"name\": \"deep\", \"a\":\n" + std::string(40000, '[') + std::string(40000, ']') + "}");
  ASSERT_GE(fs::file_size(d / "deep.json"), 80000u);
  for (const char* cmd : {"check", "run"}) {
    std::vector<std::string> args{cmd, (d / "deep.json").string()};
    if (std::string(cmd) == "run") args.insert(args.end(), {"--out", (d / "out").string()});
    const Outcome o = run(args, kAddressSpace);
    // The object is level 1: the 256th '[' (column 256 of line 2) opens level 257.
    EXPECT_REFUSED(o, "deep.json: line 2, column 256: arrays and objects nested deeper than 256 levels");
  }
  EXPECT_FALSE(fs::exists(d / "out"));
}

TEST(CliLimits, LongKeysAtEveryLevelParseInMemoryLinearInTheInput) {
  SKIP_UNDER_ASAN();
  // 250 levels (inside the depth limit), each key 40 KB: 10 MB of text. A parser keeping the
  // whole path at every level holds 250²/2 × 40 KB = 1.25 GB, beyond the 512 MiB it may use.
  const fs::path d = scratch("keys");
  std::string text = "{\"name\": \"keys\"";
  for (int i = 0; i < 250; ++i) text += ", \"" + std::to_string(i) + std::string(40000, 'k') + "\": {\"x\": 1";
  text += std::string(250, '}') + "}";
  write(d / "keys.json", text);
  const Outcome o = run({"check", (d / "keys.json").string()}, kAddressSpace);
  EXPECT_REFUSED(o, "$.materials: required value is missing");  // parsed; the case lacks the rest
}

TEST(CliLimits, AFileLargerThanTheLimitIsRefusedWithThePositionWhereItPassesIt) {
  const fs::path d = scratch("size");
  const std::string head = "{\n  \"name\": \"big\",\n";
  write(d / "big.json", head);
  const std::uintmax_t limit = std::uintmax_t(512) << 20;
  fs::resize_file(d / "big.json", limit + 4096);  // sparse: no disk used
  const std::string where = "big.json: line 3, column " + std::to_string(limit - head.size() + 1) + " (byte " +
                            std::to_string(limit + 1) + "): the case file is larger than 512 MiB";
  EXPECT_REFUSED(run({"check", (d / "big.json").string()}, kAddressSpace), where);
  EXPECT_REFUSED(run({"run", (d / "big.json").string(), "--out", (d / "out").string()}), where);
  EXPECT_FALSE(fs::exists(d / "out"));
  fs::remove(d / "big.json");
}

TEST(CliLimits, DevZeroAndAFifoAreRefusedWithoutBeingRead) {
  const fs::path d = scratch("kinds");
  // /dev/zero was read for 2 GB before failing; under 512 MiB it would be a crash.
  EXPECT_REFUSED(run({"check", "/dev/zero"}, kAddressSpace), "/dev/zero: is a character device, not a case file");
  EXPECT_REFUSED(run({"run", "/dev/zero", "--out", (d / "out").string()}), "is a character device");
  EXPECT_REFUSED(run({"verify", "/dev/zero", "--out", (d / "vout").string()}), "is a character device");
  // A FIFO with no writer: opening it to read would block for ever (the child's alarm fails the test).
  ASSERT_EQ(::mkfifo((d / "fifo.json").c_str(), 0600), 0);
  EXPECT_REFUSED(run({"check", (d / "fifo.json").string()}), "fifo.json: is a FIFO (named pipe), not a case file");
  EXPECT_REFUSED(run({"check", d.string()}), "is a directory, not a case file");
  EXPECT_FALSE(fs::exists(d / "out"));
  EXPECT_FALSE(fs::exists(d / "vout"));
}

TEST(CliLimits, ADropCountNoMachineHoldsIsRefusedByCheckAndRunNamingTheField) {
  const fs::path d = scratch("count");
  json c = read_json(kCases / "silo_fill.json");
  c["drops"]["count"] = 1000000000;  // was: check passed, run died in std::bad_alloc (exit 4)
  write(d / "fill.json", c.dump(1));
  const std::string want = "$.drops.count: the run would need about ";
  EXPECT_REFUSED(run({"check", (d / "fill.json").string()}), want);
  EXPECT_REFUSED(run({"run", (d / "fill.json").string(), "--out", (d / "out").string()}), want);
  EXPECT_REFUSED(run({"verify", (d / "fill.json").string(), "--out", (d / "vout").string()}), want);
  EXPECT_FALSE(fs::exists(d / "out"));
  EXPECT_FALSE(fs::exists(d / "vout"));
  // The estimate is printed for a case that fits, by check and in the run's banner, and recorded.
  const Outcome ok = run({"check", (kCases / "silo_fill.json").string()});
  EXPECT_EQ(ok.code, 0) << ok.output;
  EXPECT_NE(ok.output.find("memory estimate for a run: "), std::string::npos) << ok.output;
  EXPECT_NE(ok.output.find("6000 drops"), std::string::npos) << ok.output;
  write(d / "good.json", kGood);
  const Outcome ran = run({"run", (d / "good.json").string(), "--out", (d / "good").string()});
  ASSERT_EQ(ran.code, 0) << ran.output;
  EXPECT_NE(ran.output.find("[limits] memory estimate "), std::string::npos) << ran.output;
  EXPECT_GT(read_json(d / "good" / "summary.json")["memory"]["estimated_bytes"].get<double>(), 0.0);
}

TEST(CliLimits, NamesThatWouldLeaveTheResultDirectoryAreRefusedWithTheirPath) {
  const fs::path d = scratch("names");
  const std::vector<std::pair<std::string, std::string>> bad{
      {"..", "which names a directory"},
      {"a/b", "must not contain '/'"},
      {std::string("a\x01" "b"), "must not contain a control character (byte 1)"},
      {std::string(300, 'n'), "is 300 bytes long"}};
  const json base = json::parse(kGood);
  const json verified = read_json(kCases / "free_fall_contact.json");
  for (const auto& [name, why] : bad) {
    SCOPED_TRACE(why);
    json c = base;
    c["name"] = name;
    write(d / "case.json", c.dump());
    EXPECT_REFUSED(run({"check", (d / "case.json").string()}), "$.name: the name ");
    EXPECT_REFUSED(run({"run", (d / "case.json").string(), "--out", (d / "out").string()}), why);
    json p = base;
    p["output"]["probes"][0]["name"] = name;
    write(d / "probe.json", p.dump());
    EXPECT_REFUSED(run({"run", (d / "probe.json").string(), "--out", (d / "out").string()}),
                   "$.output.probes[0].name: the name ");
    // A variant value and an axis name (verify writes <out>/<case>/<axis>=<value>/).
    json v = verified;
    json& axis = v["verify"]["variants"]["integrator"];
    axis[name] = axis["velocity_verlet"];
    axis.erase("velocity_verlet");
    write(d / "variant.json", v.dump());
    EXPECT_REFUSED(run({"check", (d / "variant.json").string()}), "$.verify.variants.integrator." + name + ": ");
    EXPECT_REFUSED(run({"verify", (d / "variant.json").string(), "--out", (d / "vout").string()}), why);
    json a = verified;
    a["verify"]["variants"][name] = a["verify"]["variants"]["integrator"];
    a["verify"]["variants"].erase("integrator");
    write(d / "axis.json", a.dump());
    EXPECT_REFUSED(run({"check", (d / "axis.json").string()}), "$.verify.variants." + name + ": ");
  }
  EXPECT_FALSE(fs::exists(d / "out"));
  EXPECT_FALSE(fs::exists(d / "vout"));
  EXPECT_FALSE(fs::exists(d.parent_path() / "b"));
}

TEST(CliLimits, TwoCasesWithOneNameInOneVerifyAreRefusedBeforeAnythingRuns) {
  const fs::path d = scratch("dupes");
  fs::copy_file(kCases / "free_fall_contact.json", d / "first.json");
  fs::copy_file(kCases / "free_fall_contact.json", d / "second.json");
  const Outcome o = run({"verify", (d / "first.json").string(), (d / "second.json").string(), "--out", (d / "vout").string()});
  EXPECT_REFUSED(o, (d / "second.json").string() + " $.name: the case name \"free_fall_contact\" is also the name of "
                                                    "the case in " + (d / "first.json").string());
  EXPECT_FALSE(fs::exists(d / "vout"));
  const Outcome c = run({"compare", (d / "first.json").string(), (d / "second.json").string(), "--out",
                         (d / "cout").string(), "--codes", "silodem"});
  EXPECT_REFUSED(c, "is also the name of the case in");
  EXPECT_FALSE(fs::exists(d / "cout"));
}

TEST(CliLimits, AFileLargerThanTheMemoryLeftIsRefusedBeforeItIsRead) {
  SKIP_UNDER_ASAN();
  // 100 MB (sparse) under a 64 MiB address space: refused before any of it is held.
  const fs::path d = scratch("room");
  write(d / "wide.json", "{\"name\": \"wide\",");
  fs::resize_file(d / "wide.json", std::uintmax_t(100) << 20);
  const Outcome o = run({"check", (d / "wide.json").string()}, rlim_t(64) << 20);
  EXPECT_REFUSED(o, "wide.json: the case file is 104857600 bytes, more than the ");
  EXPECT_NE(o.output.find("(the address-space limit (ulimit -v) less what is mapped)"), std::string::npos) << o.output;
  fs::remove(d / "wide.json");
}

TEST(CliLimits, ADocumentLargerThanTheMemoryLeftStopsTheParserCleanly) {
  SKIP_UNDER_ASAN();
  // 9 MB of empty arrays: each "[]," of text becomes about 50 bytes of document, some 150 MB,
  // under a 128 MiB address space. The parser stops at its budget (was: std::bad_alloc, exit 4,
  // or an abort when the half-built document could not be taken apart).
  const fs::path d = scratch("dom");
  std::string text = "{\"name\": \"dom\", \"a\": [";
  for (int i = 0; i < 3000000; ++i) text += "[],";
  write(d / "dom.json", text + "[]]}");
  const Outcome o = run({"check", (d / "dom.json").string()}, rlim_t(128) << 20);
  EXPECT_REFUSED(o, "dom.json: reading the case file into memory takes more than ");
  EXPECT_EQ(run({"check", (d / "dom.json").string()}).code, 2);  // without the limit: read, then refused as a case
  fs::remove(d / "dom.json");
}
