// silodem-mpi (issue 31 §3, docs/domain-decomposition.md): one run shared among MPI processes gives
// the result files of the one-process run bit for bit. The oracle is `silodem run` itself on one
// thread: 1,000 frictional grains with rolling resistance fall into a cylinder of wall balls and
// pile up, renumbered every 400 steps (balls change process with their contact history) and
// redistributed whenever they have moved half the ghost margin. state.sds and series.csv
// (energies, contacts, the walls' resultant) must be byte-equal on 2 and on 3 processes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "../../harness/scratch_case.hpp"
#include "harness/backends/subprocess.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json falling_bed() {
  json grain = {{"density", 2500.0}, {"stiffness", 1e5}, {"restitution", 0.3}, {"reference_radius", 0.0045},
                {"tangential_damping_ratio", 0.5}, {"friction", 0.5}, {"rolling_friction", 0.1}};
  json wall = {{"density", 7800.0}, {"stiffness", 1e5}, {"damping", 2.0}, {"friction", 0.3}, {"tangential_damping_ratio", 0.5}};
  return {{"format", "silodem-case/1"},
          {"name", "ranks_bed"},
          {"seed", 7},
          {"contact", {{"tangential", "linear_history"}, {"rolling", "epsd"}}},
          {"materials", {{"grain", grain}, {"wall", wall}}},
          {"walls", {{{"name", "mantle"}, {"type", "cylinder"}, {"material", "wall"}, {"radius", {0.004, 0.005}},
                      {"spacing", 0.006}, {"centre", {0.0, 0.0, -0.02}}, {"diameter", 0.12}, {"height", 0.3}},
                     {{"name", "bottom"}, {"type", "disk"}, {"material", "wall"}, {"radius", {0.004, 0.005}},
                      {"spacing", 0.006}, {"centre", {0.0, 0.0, 0.0}}, {"diameter", 0.132}}}},
          {"generate", {{{"name", "g"}, {"type", "random"}, {"material", "grain"}, {"radius", {0.004, 0.005}},
                         {"region", {{"shape", "cylinder"}, {"centre", {0, 0}}, {"radius", 0.05}, {"z", {0.01, 0.2}}}},
                         {"count", 1000}, {"velocity", {0.3, 0.0, -0.2}}}}},
          {"integrator", {{"scheme", "velocity_verlet"}}},
          {"neighbour", {{"sort_interval_steps", 400}}},
          {"time", {{"dt_per_contact_time", 0.04}, {"duration", 0.12}}},
          {"output", {{"series_interval", 0.002}}}};
}

std::string bytes_of(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// mpirun -np N silodem-mpi ARGS in `dir`, output to `log`; the exit status.
int mpirun(int ranks, const std::vector<std::string>& args, const fs::path& dir, const fs::path& log) {
  std::vector<std::string> argv = {"mpirun", "--oversubscribe", "-np", std::to_string(ranks), SILODEM_MPI_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return harness::run_process(argv, {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"}, dir, log, 600.0)
      .exit_status;
}

}  // namespace

TEST(Ranks, TwoAndThreeProcessesGiveTheOneProcessRunBitForBit) {
  if (harness::find_on_path("mpirun").empty()) GTEST_SKIP() << "mpirun not found (Debian's openmpi-bin)";
  const fs::path dir = test_scratch::with_case("silodem_test_mpi_ranks", "bed.json", falling_bed());
  ASSERT_EQ(harness::run_process({SILODEM_BINARY, "run", "bed.json", "--out", "one", "--quiet"}, {}, dir, dir / "one.log", 600.0)
                .exit_status, 0) << harness::tail(dir / "one.log", 10);
  const json one = json::parse(std::ifstream(dir / "one" / "summary.json"));
  // The run exercises what the decomposition must carry: contacts with tangential and rolling
  // springs (their history moves with the balls), and the walls' load.
  ASSERT_GT(one["energy"]["elastic_tangential"].get<double>(), 0.0);
  ASSERT_GT(one["energy"]["elastic_rolling"].get<double>(), 0.0);
  ASSERT_LT(one["wall_force"][2].get<double>(), 0.0);
  for (const int ranks : {2, 3}) {
    const std::string out = "ranks" + std::to_string(ranks);
    ASSERT_EQ(mpirun(ranks, {"run", "bed.json", "--out", out, "--quiet"}, dir, dir / (out + ".log")), 0)
        << harness::tail(dir / (out + ".log"), 10);
    const json s = json::parse(std::ifstream(dir / out / "summary.json"));
    EXPECT_EQ(s["run"]["ranks"], ranks);
    EXPECT_GT(s["run"]["redistributions"].get<long>(), 3);  // the renumberings at least
    EXPECT_EQ(s["run"]["steps"], one["run"]["steps"]);
    EXPECT_TRUE(bytes_of(dir / out / "state.sds") == bytes_of(dir / "one" / "state.sds")) << out << ": state.sds differs";
    EXPECT_TRUE(bytes_of(dir / out / "series.csv") == bytes_of(dir / "one" / "series.csv")) << out << ": series.csv differs";
    EXPECT_EQ(s["energy"], one["energy"]);
    EXPECT_EQ(s["wall_force"], one["wall_force"]);
  }
}

TEST(Ranks, AFeatureTheDecompositionDoesNotCoverIsRefusedByName) {
  if (harness::find_on_path("mpirun").empty()) GTEST_SKIP() << "mpirun not found (Debian's openmpi-bin)";
  json c = falling_bed();
  c["equilibrium"] = {{"check_interval_steps", 100}};
  const fs::path dir = test_scratch::with_case("silodem_test_mpi_refusal", "bed.json", c);
  EXPECT_EQ(mpirun(2, {"run", "bed.json", "--out", "out", "--quiet"}, dir, dir / "run.log"), 2);
  EXPECT_NE(harness::tail(dir / "run.log", 20).find("equilibrium"), std::string::npos) << harness::tail(dir / "run.log", 20);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(Ranks, AnOutputDirectorySilodemDidNotWriteIsLeftAlone) {
  if (harness::find_on_path("mpirun").empty()) GTEST_SKIP() << "mpirun not found (Debian's openmpi-bin)";
  const fs::path dir = test_scratch::with_case("silodem_test_mpi_output", "bed.json", falling_bed());
  fs::create_directories(dir / "mine");
  std::ofstream(dir / "mine" / "notes.txt") << "not silodem's";
  EXPECT_NE(mpirun(2, {"run", "bed.json", "--out", "mine", "--quiet"}, dir, dir / "run.log"), 0);
  EXPECT_EQ(bytes_of(dir / "mine" / "notes.txt"), "not silodem's");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "mine"), fs::directory_iterator()), 1);
}
