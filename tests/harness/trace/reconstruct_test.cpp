// The rebuild path every reference code goes through, applied to silodem's own dump: it must give
// back silodem's own probes and kinetic energy (an independent path through dump text → states →
// probes), and the dump reader must refuse a malformed file with its line number.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "harness/backends/translation.hpp"
#include "harness/result_files.hpp"
#include "harness/trace/dump_reader.hpp"
#include "harness/trace/reconstruct.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

// collision_restitution run by silodem into `dir` with a dump of every step (the test's own
// scratch, and `<dir>_rebuilt` beside it, emptied first).
static silodem::CaseConfig run_dumping_every_step(const fs::path& dir) {
  std::ifstream in(std::string(SILODEM_SOURCE_DIR) + "/cases/collision_restitution.json");
  json c = json::parse(in);
  c["output"]["dump_interval_steps"] = 1;
  const auto cfg = silodem::load_case(c);
  fs::remove_all(dir);
  fs::remove_all(dir.string() + "_rebuilt");
  silodem::run_case(cfg, {dir, false, false});
  return cfg;
}

TEST(Reconstruct, RebuildsTheSolversOwnProbesFromItsDump) {
  const fs::path dir = fs::temp_directory_path() / "silodem_reconstruct", rebuilt_dir = dir.string() + "_rebuilt";
  const auto cfg = run_dumping_every_step(dir);
  std::string why;
  const auto tr = harness::translate(cfg, why);
  harness::reconstruct_result(cfg, tr, dir / "dump.txt", rebuilt_dir, {{"code", "test"}});
  const auto own = harness::read_result(dir), rebuilt = harness::read_result(rebuilt_dir);
  for (const char* probe : {"z030_equal_p0", "z090_wall_p5", "z000_unequal_p3"}) {
    const auto a = own.probe(probe), b = rebuilt.probe(probe);
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_NEAR(b.number(0, "restitution"), a.number(0, "restitution"), 1e-12) << probe;
    EXPECT_NEAR(b.number(0, "duration"), a.number(0, "duration"), 1e-15) << probe;
  }
  EXPECT_NEAR(rebuilt.summary["energy"]["kinetic"].get<double>(), own.summary["energy"]["kinetic"].get<double>(),
              1e-12 * own.summary["energy"]["initial"].get<double>());
  EXPECT_EQ(rebuilt.summary["run"]["frames"], own.summary["run"]["steps"].get<long>() + 1);
}

TEST(DumpReader, RefusesAMalformedFrameNamingTheLine) {
  const fs::path f = fs::temp_directory_path() / "silodem_bad.dump";
  std::ofstream(f) << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS mm mm mm\n0 1\n0 1\n0 1\n"
                      "ITEM: ATOMS id mass radius x y z vx vy vz fx fy fz\n1 1 1 0 0 0 0 0 0 0 0 0\n";
  harness::DumpReader r(f);
  harness::DumpFrame fr;
  try {
    r.next(fr);
    FAIL() << "accepted a truncated frame";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(":10: truncated atom list"), std::string::npos) << e.what();
  }
}

// A code that stopped early leaves a dump whose last frame is more than one interval before the
// run's end: the rebuild refuses it, naming the step, rather than give a result that looks whole.
TEST(Reconstruct, RefusesADumpThatEndsBeforeTheRun) {
  const fs::path dir = fs::temp_directory_path() / "silodem_reconstruct_cut", rebuilt_dir = dir.string() + "_rebuilt";
  const auto cfg = run_dumping_every_step(dir);
  std::string why;
  const auto tr = harness::translate(cfg, why);
  // Keep the frames of the first half of the run.
  std::ifstream whole(dir / "dump.txt");
  std::ofstream cut(dir / "cut.txt");
  std::string line, step;
  while (std::getline(whole, line)) {
    if (line == "ITEM: TIMESTEP") {
      std::getline(whole, step);
      if (std::stol(step) > tr.steps / 2) break;
      line += "\n" + step;
    }
    cut << line << "\n";
  }
  cut.close();
  try {
    harness::reconstruct_result(cfg, tr, dir / "cut.txt", rebuilt_dir, {{"code", "test"}});
    FAIL() << "accepted a dump that ends at half the run";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the code stopped before the run's end"), std::string::npos) << e.what();
  }
  // The whole dump is accepted.
  EXPECT_NO_THROW(harness::reconstruct_result(cfg, tr, dir / "dump.txt", rebuilt_dir, {{"code", "test"}}));
}

// silodem dumps its rows in its particle order, which its spatial sorting changes during the run
// (free_fall_contact's three mobile balls: tags 5, 7, 8 at the start, 8, 5, 7 at the end). The
// rebuild follows each ball by its tag, so its probes are the run's own: the bouncer's last state
// and the twin's contacts (a rebuild that kept the first frame's indices gave the twin's position as
// the bouncer's).
TEST(Reconstruct, FollowsEachBallByItsTagWhenTheDumpsRowOrderChanges) {
  std::ifstream in(std::string(SILODEM_SOURCE_DIR) + "/cases/free_fall_contact.json");
  json c = json::parse(in);
  c["output"]["dump_interval_steps"] = 1;
  const auto cfg = silodem::load_case(c);
  const fs::path dir = fs::temp_directory_path() / "silodem_reconstruct_order", rebuilt_dir = dir.string() + "_rebuilt";
  fs::remove_all(dir);
  fs::remove_all(rebuilt_dir);
  silodem::run_case(cfg, {dir, false, false});
  harness::DumpReader reader(dir / "dump.txt");
  harness::DumpFrame frame;
  std::vector<std::int64_t> first_order, last_order;
  while (reader.next(frame)) {
    last_order.clear();
    for (const auto& a : frame.atoms) last_order.push_back(a.id);
    if (first_order.empty()) first_order = last_order;
  }
  ASSERT_NE(first_order, last_order) << "the run no longer reorders its balls: this test needs another case";
  std::string why;
  const auto tr = harness::translate(cfg, why);
  harness::reconstruct_result(cfg, tr, dir / "dump.txt", rebuilt_dir, {{"code", "test"}});
  const auto own = harness::read_result(dir).summary["probes"], rebuilt = harness::read_result(rebuilt_dir).summary["probes"];
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(rebuilt["bouncer"]["final_position"][k].get<double>(), own["bouncer"]["final_position"][k].get<double>(), 1e-15);
    EXPECT_NEAR(rebuilt["bouncer"]["final_velocity"][k].get<double>(), own["bouncer"]["final_velocity"][k].get<double>(), 1e-14);
  }
  EXPECT_EQ(rebuilt["bouncer"]["apexes"], own["bouncer"]["apexes"]);
  EXPECT_EQ(rebuilt["twin_high"]["events"], own["twin_high"]["events"]);
  EXPECT_NEAR(rebuilt["twin_high"]["max_gap"].get<double>(), own["twin_high"]["max_gap"].get<double>(), 1e-15);
}
