#include "harness/sweep/job_plan.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "harness/backends/subprocess.hpp"
#include "harness/compare.hpp"
#include "harness/result_files.hpp"
#include "harness/sweep/run_inputs.hpp"
#include "harness/verify.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/output/checked_file.hpp"
#include "silodem/output/manifest.hpp"
#include "silodem/run/simulation.hpp"

namespace harness {

namespace fs = std::filesystem;
using nlohmann::json;

double expected_work(const silodem::CaseConfig& cfg, const std::string& code) {
  if (!(cfg.dt > 0.0)) return 0.0;
  const double balls = double(cfg.balls.size()) + (cfg.drops ? double(cfg.drops->count) : 0.0);
  const double steps = std::max(0.0, cfg.duration / cfg.dt - double(cfg.start_step));
  const double slowness = code == "yade" ? 10.0 : code == "silodem" ? 1.0 : 2.0;
  return balls * steps * slowness;
}

std::vector<std::size_t> longest_first(const SweepPlan& plan, std::vector<std::size_t> jobs) {
  std::stable_sort(jobs.begin(), jobs.end(), [&](std::size_t a, std::size_t b) {
    return plan.jobs[a].expected_work > plan.jobs[b].expected_work;
  });
  return jobs;
}

fs::path SweepPlan::log(std::size_t k) const { return dir / "jobs" / (std::to_string(k) + ".log"); }
fs::path SweepPlan::status(std::size_t k) const { return dir / "jobs" / (std::to_string(k) + ".status.json"); }

void write_plan(const SweepPlan& plan, const std::string& silodem_binary) {
  json jobs = json::array();
  for (std::size_t k = 0; k < plan.jobs.size(); ++k) {
    const SweepJob& j = plan.jobs[k];
    jobs.push_back({{"index", k},
                    {"case_file", j.case_file.string()},
                    {"case", j.case_name},
                    {"variant", j.variant},
                    {"out_dir", j.out_dir.string()},
                    {"kind", j.kind},
                    {"code", j.code},
                    {"seed", j.seed},
                    {"from_state", j.from_state.string()},
                    {"inputs", j.inputs},
                    {"command", silodem_binary + " job " + shell_quote(plan.file().string()) + " " + std::to_string(k)}});
  }
  fs::create_directories(plan.dir / "jobs");
  const json doc = {{"format", "silodem-plan/1"},
                    {"what", "silodem's runs: each job one run into its own folder; compare's \"run\" and \"seed_run\" "
                             "jobs continue from the state their case's \"state\" job wrote"},
                    {"ranks", plan.ranks},
                    {"launcher", plan.launcher},
                    {"jobs", jobs}};
  silodem::write_file_checked(plan.file(), doc.dump(1) + "\n");
}

SweepPlan read_plan(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the plan");
  json doc;
  try {
    doc = json::parse(in);
    if (doc.at("format") != "silodem-plan/1") throw std::runtime_error("not a silodem-plan/1 file");
    SweepPlan plan;
    plan.dir = fs::absolute(file).parent_path();
    plan.ranks = doc.value("ranks", 1);
    plan.launcher = doc.value("launcher", std::string("mpirun"));
    for (const json& j : doc.at("jobs"))
      plan.jobs.push_back({j.at("case_file").get<std::string>(), j.at("case").get<std::string>(),
                           j.at("variant").get<std::string>(), j.at("out_dir").get<std::string>(),
                           j.value("kind", std::string("verify")), j.value("code", std::string("silodem")),
                           j.value("seed", -1), j.value("from_state", std::string()), j.value("inputs", json())});
    return plan;
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

namespace {

void write_status(const SweepPlan& plan, std::size_t k, const json& status) {
  silodem::write_file_checked(plan.status(k), status.dump() + "\n");
}

}  // namespace

bool run_job(const SweepPlan& plan, std::size_t k, double progress_every) {
  if (k >= plan.jobs.size())
    throw std::runtime_error(plan.file().string() + " has " + std::to_string(plan.jobs.size()) + " jobs, no job " +
                             std::to_string(k));
  const SweepJob& job = plan.jobs[k];
  std::error_code ec;
  fs::remove(plan.status(k), ec);  // an earlier attempt's status (the sweep's own file)
  try {
    if (job.kind != "verify") {
      const std::string why = run_compare_job(job, {plan.ranks, plan.launcher}, progress_every);
      write_status(plan, k, why.empty() ? json{{"state", "done"}, {"inputs", job.inputs}} : json{{"state", "failed"}, {"reason", why}});
      return why.empty();
    }
    const silodem::CaseConfig cfg = silodem::load_case(verify_variant_json(job.case_file, job.variant));
    silodem::RunOptions run{job.out_dir, progress_every >= 0.0, false};
    run.progress_every = std::max(0.0, progress_every);
    silodem::run_case(cfg, run);
    write_status(plan, k, {{"state", "done"}});
    return true;
  } catch (const std::exception& e) {
    write_status(plan, k, {{"state", "failed"}, {"reason", e.what()}});
    return false;
  }
}

std::optional<std::string> job_failure(const SweepPlan& plan, std::size_t k) {
  std::ifstream in(plan.status(k));
  std::string why;
  if (!in) {
    why = "no status file: the job was killed, ran out of time or never started";
  } else {
    try {
      const json s = json::parse(in);
      if (s.at("state") == "done") return std::nullopt;
      why = s.at("reason").get<std::string>();
    } catch (const std::exception& e) {
      why = std::string("unreadable status file: ") + e.what();
    }
  }
  if (fs::exists(plan.log(k))) why += " (log " + plan.log(k).string() + ", last lines:\n" + tail(plan.log(k), 8) + ")";
  return why;
}

bool job_complete(const SweepPlan& plan, std::size_t k) {
  const SweepJob& job = plan.jobs[k];
  try {
    const ResultSet rs = read_result(job.out_dir);
    return without_judging(rs.summary.at("input")) == without_judging(verify_variant_json(job.case_file, job.variant));
  } catch (const std::exception&) {
    return false;  // absent, incomplete, or not matching its manifest: run it
  }
}

namespace {

/// A status written before run digests (inputs with the case file's digest, "case_digest") stands
/// for the job's inputs now if the case file is byte for byte the one it ran.
bool legacy_inputs_match(const json& recorded, const SweepJob& job) {
  if (!recorded.contains("case_digest") || recorded.contains("run_digest")) return false;
  json now = job.inputs;
  now.erase("run_digest");
  now["case_digest"] = silodem::file_digest(job.case_file);
  return recorded == now;
}

}  // namespace

bool compare_job_complete(const SweepPlan& plan, std::size_t k) {
  const SweepJob& job = plan.jobs[k];
  try {
    std::ifstream in(plan.status(k));
    if (!in || job.inputs.is_null()) return false;
    json status = json::parse(in);
    in.close();
    if (status.at("state") != "done") return false;
    const bool legacy = legacy_inputs_match(status.at("inputs"), job);
    if (!legacy && status.at("inputs") != job.inputs) return false;
    read_result(job.out_dir);  // throws unless complete and verified against its manifest
    if (legacy) {  // recorded again with the run digest, so a later change of judging keeps it too
      status["inputs"] = job.inputs;
      write_status(plan, k, status);
    }
    return true;
  } catch (const std::exception&) {
    return false;  // no status, another job's or an earlier case's, or a damaged result: run it
  }
}

}  // namespace harness
