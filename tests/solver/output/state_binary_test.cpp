// The compact state file (output/state_binary.hpp): a run's state.sds holds bit for bit what its
// state.json holds (the JSON writer is the independent one: text at full precision), a case can
// start from it, and a damaged file is refused with the reason.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/output/state_binary.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/run/simulation.hpp"

using namespace silodem;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path tmp(const std::string& name) {
  static std::set<std::string> cleared;
  const fs::path d = fs::temp_directory_path() / ("silodem_state_binary_test_" + name);
  if (cleared.insert(name).second) fs::remove_all(d);
  return d;
}

/// Frictional grains (so they spin) generated on a lattice over a disk wall, falling for 0.12 s (onto the floor, where they spin).
json spinning_pile() {
  return json::parse(R"({
    "format": "silodem-case/1", "name": "binary_state", "seed": 11,
    "contact": {"tangential": "linear_history"},
    "materials": {"grain": {"density": 2500, "stiffness": 1e5, "restitution": 0.5, "reference_radius": 0.004,
                            "friction": 0.5}},
    "walls": [{"name": "floor", "type": "disk", "material": "grain", "radius": [0.004, 0.005], "spacing": 0.006,
               "centre": [0, 0, 0], "diameter": 0.06}],
    "generate": [{"name": "g", "type": "random", "material": "grain", "radius": [0.0035, 0.0045], "count": 40,
                  "region": {"shape": "cylinder", "centre": [0, 0], "radius": 0.025, "z": [0.006, 0.08]}}],
    "integrator": {"scheme": "velocity_verlet"},
    "time": {"dt_per_contact_time": 0.04, "duration": 0.12}
  })");
}

void expect_same(const StateSnapshot& a, const StateSnapshot& b) {
  ASSERT_EQ(a.balls.size(), b.balls.size());
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.dt, b.dt);
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    const BallSpec &x = a.balls[i], &y = b.balls[i];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.material, y.material);
    EXPECT_EQ(x.fixed, y.fixed);
    EXPECT_EQ(x.radius, y.radius);
    EXPECT_EQ(x.position, y.position) << x.id;
    EXPECT_EQ(x.velocity, y.velocity) << x.id;
    EXPECT_EQ(x.angular_velocity, y.angular_velocity) << x.id;
  }
}

}  // namespace

TEST(StateBinary, HoldsBitForBitWhatStateJsonHolds) {
  const fs::path dir = tmp("run");
  run_case(load_case(spinning_pile()), {dir, false, false});
  ASSERT_TRUE(is_binary_state(dir / "state.sds"));
  EXPECT_FALSE(is_binary_state(dir / "state.json"));
  const StateSnapshot bin = read_state(dir / "state.sds"), text = read_state(dir / "state.json");
  expect_same(bin, text);
  std::size_t spinning = 0;
  for (const auto& b : bin.balls) spinning += b.angular_velocity.norm() > 0.0;
  EXPECT_GT(spinning, 0u);  // the angular velocities are there to compare
  // Ids, a material, a flag and 13 doubles: under 120 bytes a ball, against state.json's 200 and more.
  const double per_ball = double(fs::file_size(dir / "state.sds")) / double(bin.balls.size());
  EXPECT_LT(per_ball, 120.0);
  EXPECT_GT(double(fs::file_size(dir / "state.json")) / double(bin.balls.size()), 1.5 * per_ball);
}

TEST(StateBinary, ACaseStartsFromTheStateFileAsFromTheSameBallsListed) {
  const fs::path dir = tmp("from");
  run_case(load_case(spinning_pile()), {dir, false, false});
  json from_file = spinning_pile();
  from_file.erase("generate");
  from_file.erase("walls");
  from_file["balls"] = {{"state_file", (dir / "state.sds").string()}};
  const CaseConfig a = load_case(from_file);
  // The same balls listed in JSON, as state.json holds them.
  json listed = from_file;
  std::ifstream in(dir / "state.json");
  listed["balls"] = json::parse(in)["balls"];
  const CaseConfig b = load_case(listed);
  ASSERT_EQ(a.balls.size(), b.balls.size());
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    EXPECT_EQ(a.balls[i].id, b.balls[i].id);
    EXPECT_EQ(a.balls[i].position, b.balls[i].position);
    EXPECT_EQ(a.balls[i].angular_velocity, b.balls[i].angular_velocity);
  }
  run_case(a, {tmp("a"), false, false});
  run_case(b, {tmp("b"), false, false});
  expect_same(read_state(tmp("a") / "state.sds"), read_state(tmp("b") / "state.sds"));
}

TEST(StateBinary, ARelativeStateFileIsFoundBesideTheCaseFile) {
  const fs::path dir = tmp("relative");
  run_case(load_case(spinning_pile()), {dir / "run", false, false});
  json c = spinning_pile();
  c.erase("generate");
  c.erase("walls");
  c["balls"] = {{"state_file", "run/state.sds"}};
  std::ofstream(dir / "case.json") << c.dump();
  EXPECT_EQ(load_case_file(dir / "case.json").balls.size(), read_state(dir / "run" / "state.sds").balls.size());
}

TEST(StateBinary, ADamagedFileIsRefusedWithItsReason) {
  const fs::path dir = tmp("damaged");
  run_case(load_case(spinning_pile()), {dir, false, false});
  const fs::path good = dir / "state.sds", cut = dir / "cut.sds";
  fs::copy_file(good, cut);
  fs::resize_file(cut, fs::file_size(good) - 8);
  try {
    read_state(cut);
    FAIL() << "a truncated state was read";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
  // A material index beyond the header's list.
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t data = bytes.find('\n') + 1;
  const json header = json::parse(bytes.substr(0, data));
  std::uint64_t material_at = 0;
  for (const auto& c : header["columns"])
    if (c["name"] == "material") material_at = c["offset"].get<std::uint64_t>();
  bytes[data + material_at] = 7;
  std::ofstream(dir / "bad_material.sds", std::ios::binary) << bytes;
  try {
    read_state(dir / "bad_material.sds");
    FAIL() << "an unknown material index was read";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("material index 7"), std::string::npos) << e.what();
  }
  // Headers a hostile or broken writer could make: a second id column reaching past the data, a
  // field of the wrong JSON type. Each is a CaseError, never a read out of bounds.
  const auto with_header = [&](const std::string& name, const std::function<void(json&)>& edit) {
    json h = header;
    edit(h);
    h.erase("format");  // written first, as the writer does: the file is recognised by it
    std::ofstream(dir / name, std::ios::binary) << "{\"format\":\"silodem-state/2\"," << h.dump().substr(1) << "\n"
                                                << bytes.substr(data);
    return dir / name;
  };
  const auto refused = [&](const fs::path& f, const std::string& words) {
    try {
      read_state(f);
      ADD_FAILURE() << f;
    } catch (const CaseError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << words << " in: " << e.what();
    }
  };
  refused(with_header("twice.sds", [](json& h) {
            json extra = h["columns"][0];
            extra["bytes"] = 1000000000;
            h["columns"].push_back(extra);
          }), "listed twice");
  refused(with_header("materials.sds", [](json& h) { h["materials"] = json::array({1}); }), "malformed");
  refused(with_header("columns.sds", [](json& h) { h["columns"] = 3; }), "no column list");
  // The case names the field the bad file came from.
  json c = spinning_pile();
  c.erase("generate");
  c["balls"] = {{"state_file", (dir / "cut.sds").string()}};
  try {
    load_case(c);
    FAIL();
  } catch (const CaseError& e) {
    EXPECT_EQ(e.path().rfind("$.balls.state_file", 0), 0u) << e.what();
  }
}
