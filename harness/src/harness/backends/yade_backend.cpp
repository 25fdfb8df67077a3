// YADE 2023.02a (Debian `yade`): the only C++ file that knows YADE; the physics mapping is in the
// driver (harness/yade/yade_driver.py), embedded into the binary and written next to its input.
// Run as a Python module under /usr/bin/python3.11, not through the `yade` launcher, which binds
// ports 9000 and 21000 on all interfaces (docs/reference-codes.md, Measured facts: YADE).
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/backends/reference_backend.hpp"
#include "harness/backends/subprocess.hpp"
#include "yade_driver_source.hpp"

namespace harness {

namespace {

constexpr const char* kPython = "/usr/bin/python3.11";
constexpr const char* kYadeLib = "/usr/lib/x86_64-linux-gnu/yade-double/py";

class YadeBackend final : public ReferenceBackend {
 public:
  std::string code() const override { return "yade"; }
  std::string missing() const override {
    if (::access(kPython, X_OK) != 0) return std::string(kPython) + " not found";
    if (!std::filesystem::exists(std::string(kYadeLib) + "/yade")) return std::string("yade not found (") + kYadeLib + ")";
    return "";
  }

 protected:
  std::string code_limits(const silodem::CaseConfig& cfg) const override {
    if (!cfg.contact.frictionless_linear())
      return "friction, rotation and the Hertz law are not translated for YADE yet (docs/reference-codes.md, "
             "sub-models by code)";
    if (!cfg.contact.clamp)
      return "YADE's viscoelastic law (Law2_ScGeom_ViscElPhys_Basic) always clamps the normal force at zero; "
             "the unclamped paper law has no stock equivalent";
    return "";
  }

  std::string version(const std::filesystem::path& log) const override {
    std::ifstream in(log);
    std::string l;
    while (std::getline(in, l))
      if (l.rfind("YADE ", 0) == 0) return l;
    return "yade (version not printed)";
  }

 public:
  Input write_input(const silodem::CaseConfig& cfg, const Translation& tr) const override {
    nlohmann::json types = nlohmann::json::array(), balls = nlohmann::json::array();
    // YADE's series rule skips a zero constant (a = 0 gives the pair b, where (11) gives 0), so a
    // dashpot-free material gets c = 1e-12 × the largest c instead: its pairs then have ζ ~ 1e-12.
    double c_max = 0.0;
    for (const auto& t : tr.types) c_max = std::max(c_max, t.c);
    for (const auto& t : tr.types)
      types.push_back({{"k", t.k}, {"c", t.c > 0.0 ? t.c : 1e-12 * c_max}, {"density", t.density}});
    for (const auto& b : tr.balls)
      balls.push_back({{"tag", b.tag},
                       {"type", b.type},
                       {"radius", b.radius},
                       {"fixed", b.fixed},
                       {"x", {b.x.x(), b.x.y(), b.x.z()}},
                       {"v", {b.v.x(), b.v.y(), b.v.z()}}});
    nlohmann::json events = nlohmann::json::array();
    for (const auto& ev : tr.events) {
      nlohmann::json e = {{"step", ev.step},
                          {"type", ev.type},
                          {"tags", ev.tags},
                          {"centre", {ev.centre.x(), ev.centre.y(), ev.centre.z()}},
                          {"diameter", ev.diameter},
                          {"thickness", ev.thickness}};
      if (ev.type == "insert")
        e["ball"] = {{"tag", ev.ball.tag},
                     {"type", ev.ball.type},
                     {"radius", ev.ball.radius},
                     {"fixed", false},
                     {"x", {ev.ball.x.x(), ev.ball.x.y(), ev.ball.x.z()}},
                     {"v", {ev.ball.v.x(), ev.ball.v.y(), ev.ball.v.z()}}};
      events.push_back(std::move(e));
    }
    nlohmann::json j = {{"case", cfg.name},
                              {"dt", cfg.dt},
                              {"start_step", tr.start_step},
                              {"steps", tr.steps},
                              {"events", events},
                              {"skin", tr.skin},
                              {"dump_interval", dump_interval(cfg)},
                              {"gravity", {cfg.gravity.x(), cfg.gravity.y(), cfg.gravity.z()}},
                              {"types", types},
                              {"balls", balls}};
    if (tr.outflow_below_z) j["outflow_below_z"] = *tr.outflow_below_z, j["outflow_every_steps"] = tr.outflow_every_steps;
    Input in;
    in.files = {{"case.json", j.dump(1)}, {"yade_driver.py", kYadeDriverSource}};
    in.main_file = j.dump(1);
    in.argv = {kPython, "yade_driver.py", "case.json"};
    in.env = {std::string("PYTHONPATH=") + kYadeLib, "OMP_NUM_THREADS=1"};
    return in;
  }
};

}  // namespace

std::unique_ptr<Backend> make_yade_backend() { return std::make_unique<YadeBackend>(); }

}  // namespace harness
