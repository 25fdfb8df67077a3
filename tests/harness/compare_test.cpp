// Integration: the three small cases through every backend — silodem, LAMMPS, LIGGGHTS, YADE —
// with their verdicts asserted. The reference codes must be installed (tools/setup.sh does it);
// a missing code fails this test rather than passing silently.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "harness/compare.hpp"
#include "harness/verdict_report.hpp"

namespace fs = std::filesystem;

TEST(Compare, ThreeCasesInEveryCode) {
  harness::CompareOptions opt;
  // Kept for the report test (tests/tools/report_test.py), which draws its figures from them.
  opt.out_root = fs::path(SILODEM_TEST_RESULTS) / "compare";
  opt.progress = false;
  const std::string dir = std::string(SILODEM_SOURCE_DIR) + "/cases/";
  const auto v = harness::compare_cases(
      {dir + "collision_restitution.json", dir + "cohesion_cutoff.json", dir + "free_fall_contact.json"}, opt);
  harness::write_verdict_json(opt.out_root / "verdicts.json", v);
  std::set<std::string> codes_run, cross;
  for (const auto& r : v.rows) {
    EXPECT_TRUE(r.pass || r.skipped) << r.case_name << " " << r.variant << " " << r.code << " " << r.quantity << " "
                                     << r.subject << ": " << r.measured << " vs " << r.expected << " " << r.note;
    if (r.skipped) {
      EXPECT_EQ(r.note.find("not found"), std::string::npos) << "reference code missing: " << r.note;
      EXPECT_EQ(r.note.rfind("not representable: ", 0), 0u) << r.note;
    } else {
      codes_run.insert(r.code);
    }
    if (r.code.rfind("silodem vs ", 0) == 0) cross.insert(r.code + " " + r.quantity);
  }
  for (const char* c : {"silodem", "lammps", "liggghts", "yade"}) EXPECT_TRUE(codes_run.count(c)) << c;
  // Same algorithm, same answer: restitution and contact time against every reference code.
  for (const char* c : {"lammps", "liggghts", "yade"}) {
    EXPECT_TRUE(cross.count(std::string("silodem vs ") + c + " restitution")) << c;
    EXPECT_TRUE(cross.count(std::string("silodem vs ") + c + " contact_duration")) << c;
    EXPECT_TRUE(cross.count(std::string("silodem vs ") + c + " rebound_height")) << c;
  }
}
