// VTK snapshots (output/vtk_writer.hpp), Float32 and Float64, read back by an independent reader — VTK's own
// vtkXMLPolyDataReader through read_vtk.py — and checked against the run's state.json (another
// writer) and its summary: every frame parses, has the arrays ParaView needs, the collection's
// times are step · dt, the final frame equals the final state bit for bit, and the wall balls'
// forces sum to the wall load.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void every_frame_parses_and_the_last_is_the_final_state(const std::string& precision) {
  // A few drops into a small silo with a hopper hole, frames every 50 steps (the last not on one).
  json c = json::parse(std::ifstream(fs::path(SILODEM_SOURCE_DIR) / "fuzz" / "checkpoint_case.json"));
  c.erase("checkpoint");
  c.erase("guards");
  c["time"]["duration"] = 0.001;
  c["output"]["vtk_interval_steps"] = 50;
  c["output"]["vtk_precision"] = precision;
  const silodem::CaseConfig cfg = silodem::load_case(c);
  const fs::path out = fs::temp_directory_path() / ("silodem_vtk_" + precision);
  fs::remove_all(out);
  silodem::run_case(cfg, {out, false, false});
  ASSERT_TRUE(fs::exists(out / "vtk" / "balls.pvd"));
  ASSERT_TRUE(fs::exists(out / "vtk" / "walls.pvd"));
  char dt[64];
  std::snprintf(dt, sizeof dt, "%.17g", cfg.dt);
  const std::string cmd = "/usr/bin/python3 " + (fs::path(SILODEM_SOURCE_DIR) / "tests/solver/output/read_vtk.py").string() +
                          " " + out.string() + " " + dt + " " + precision + " > " + (out.string() + ".log") + " 2>&1";
  const int s = std::system(cmd.c_str());
  std::ifstream log(out.string() + ".log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(WIFEXITED(s) && WEXITSTATUS(s) == 0) << text;
  EXPECT_NE(text.find("ok:"), std::string::npos) << text;
  std::printf("%s", text.c_str());
  fs::remove_all(out);
}

}  // namespace

TEST(VtkWriter, EveryFloat32FrameParsesAndTheLastIsTheFinalStateRounded) {
  every_frame_parses_and_the_last_is_the_final_state("float32");
}

TEST(VtkWriter, EveryFloat64FrameParsesAndTheLastIsTheFinalStateBitwise) {
  every_frame_parses_and_the_last_is_the_final_state("float64");
}
