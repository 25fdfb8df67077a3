// The executable as a user runs it: help, exit codes, and no half-written results on bad input.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {
int run(const std::string& args) {
  const int s = std::system((std::string(SILODEM_BINARY) + " " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}
fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("silodem_cli_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
const std::string kGood = R"({"name": "cli", "gravity": [0, 0, -9.81],
  "materials": {"g": {"density": 2500, "stiffness": 2e5, "damping": 6}},
  "balls": [{"id": "a", "material": "g", "radius": 0.005, "position": [0, 0, 0.0099998716005]},
            {"id": "w", "material": "g", "radius": 0.005, "position": [0, 0, 0], "fixed": true}],
  "time": {"dt": 1e-5, "duration": 0.05}})";
}  // namespace

TEST(Cli, HelpOnEveryCommand) {
  EXPECT_EQ(run("--help"), 0);
  for (const char* c : {"run", "verify", "check"}) EXPECT_EQ(run(std::string(c) + " --help"), 0) << c;
  EXPECT_EQ(run(""), 2);
  EXPECT_EQ(run("frobnicate"), 2);
}

TEST(Cli, RunWritesCompleteResults) {
  const fs::path d = scratch("good");
  std::ofstream(d / "case.json") << kGood;
  ASSERT_EQ(run("run " + (d / "case.json").string() + " --out " + (d / "out").string() + " --quiet"), 0);
  std::ifstream in(d / "out" / "summary.json");
  const auto s = nlohmann::json::parse(in);
  EXPECT_EQ(s["status"], "complete");
  EXPECT_EQ(s["run"]["steps"], 5000);
  EXPECT_TRUE(fs::exists(d / "out" / "series.csv"));
  // "DIR/" names the same directory as "DIR".
  ASSERT_EQ(run("run " + (d / "case.json").string() + " --out " + (d / "slash").string() + "/ --quiet"), 0);
  EXPECT_TRUE(fs::exists(d / "slash" / "summary.json"));
  // The ball starts at its static overlap m g/k on the wall ball (k_ij = 1e5): the wall carries
  // its weight, pushed down (the wall load is the force on the wall).
  const double m = 2500 * 4.0 / 3.0 * M_PI * 1.25e-7;
  EXPECT_NEAR(s["wall_force"][2].get<double>(), -m * 9.81, 1e-6 * m * 9.81);
}

TEST(Cli, BadInputExitsTwoAndLeavesNoOutput) {
  const fs::path d = scratch("bad");
  std::ofstream(d / "typo.json") << [] {
    auto j = nlohmann::json::parse(kGood);
    j["time"]["durration"] = 1.0;
    return j.dump();
  }();
  std::ofstream(d / "truncated.json") << kGood.substr(0, 80);
  std::ofstream(d / "negative.json") << [] {
    auto j = nlohmann::json::parse(kGood);
    j["balls"][0]["radius"] = -0.005;
    return j.dump();
  }();
  for (const char* f : {"typo.json", "truncated.json", "negative.json", "missing.json"}) {
    EXPECT_EQ(run("run " + (d / f).string() + " --out " + (d / "out").string()), 2) << f;
    EXPECT_FALSE(fs::exists(d / "out")) << f;
  }
  EXPECT_EQ(run("verify " + (d / "negative.json").string() + " --out " + (d / "vout").string()), 2);
  EXPECT_FALSE(fs::exists(d / "vout"));
}

TEST(Cli, EveryCorpusRefusalExitsTwoAndWritesNothing) {
  // tests/solver/case/corpus/expected.tsv: "-" in the second column marks the valid cases.
  const fs::path corpus = fs::path(SILODEM_SOURCE_DIR) / "tests/solver/case/corpus";
  const fs::path d = scratch("corpus");
  std::ifstream list(corpus / "expected.tsv");
  int refused = 0;
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::string file = line.substr(0, line.find('\t'));
    if (line.substr(file.size() + 1, 2) == "-\t") continue;
    const fs::path out = d / "out";
    EXPECT_EQ(run("check " + (corpus / file).string()), 2) << file;
    EXPECT_EQ(run("run " + (corpus / file).string() + " --out " + out.string() + " --quiet"), 2) << file;
    // Neither DIR nor a DIR.partial-<pid> may be left behind.
    EXPECT_TRUE(fs::is_empty(d)) << file;
    ++refused;
  }
  EXPECT_GE(refused, 50);
}

namespace {
std::string stderr_of(const std::string& args, const fs::path& log) {
  (void)std::system((std::string(SILODEM_BINARY) + " " + args + " >/dev/null 2>" + log.string()).c_str());
  std::ifstream in(log);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
}  // namespace

TEST(Cli, ProgressLinesAreWrittenOffATerminalOnlyWhenAskedAndSayRateAndTimeLeft) {
  const fs::path d = scratch("progress");
  nlohmann::json c = nlohmann::json::parse(kGood);
  c["time"]["duration"] = 3.0;  // 3e5 steps of one ball: about 1.5 s
  std::ofstream(d / "case.json") << c.dump();
  const std::string quiet_log = stderr_of("run " + (d / "case.json").string() + " --out " + (d / "a").string(), d / "a.log");
  EXPECT_EQ(quiet_log.find("steps/s"), std::string::npos) << quiet_log;  // stderr is a file: no line unasked
  const std::string log =
      stderr_of("run " + (d / "case.json").string() + " --out " + (d / "b").string() + " --progress-every 0.1", d / "b.log");
  const std::size_t at = log.find("[cli] t = ");
  ASSERT_NE(at, std::string::npos) << log;
  const std::string line = log.substr(at, log.find('\n', at) - at);
  for (const char* part : {" / 3 s (", "steps/s, ", "ball-steps/s, ", "simulated s per s | ", " left | ", "1 mobile"})
    EXPECT_NE(line.find(part), std::string::npos) << part << " in " << line;
  // One mobile ball: ball-steps per second equal steps per second.
  double steps = 0, ball_steps = 0;
  ASSERT_EQ(std::sscanf(line.substr(line.find("| ") + 2).c_str(), "%lg steps/s, %lg ball-steps/s", &steps, &ball_steps), 2)
      << line;
  EXPECT_GT(steps, 0.0);
  EXPECT_EQ(steps, ball_steps);
  EXPECT_EQ(run("run " + (d / "case.json").string() + " --out " + (d / "c").string() + " --progress-every 0"), 2);
}
