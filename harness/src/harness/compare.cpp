#include "harness/compare.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <algorithm>
#include <optional>
#include <sstream>

#include "harness/backends/backend.hpp"
#include "harness/between_codes.hpp"
#include "harness/compare_case.hpp"
#include "harness/sweep/executor.hpp"
#include "harness/sweep/run_inputs.hpp"
#include "harness/janssen_prediction.hpp"
#include "harness/case_names.hpp"
#include "harness/seed_scatter.hpp"
#include "harness/tolerance_source.hpp"
#include "harness/variants.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/case/json_reader.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/run/simulation.hpp"

namespace harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

CheckRow skip_row(const std::string& case_name, const std::string& variant, const std::string& code,
                  const std::string& why) {
  CheckRow r;
  r.case_name = case_name;
  r.variant = variant;
  r.code = code;
  r.quantity = "run";
  r.skipped = true;
  r.note = why;
  return r;
}

std::string ledger_line(const std::string& case_name, const std::string& variant, const std::string& code,
                        const json& e, const json* rebuilt) {
  // A partial ledger (a rebuild without the springs' history) has no balance: "partial" stands in.
  const auto num = [](const json& j, const char* k, const char* f) {
    if (!j.contains(k)) return std::string("partial");
    char x[48];
    std::snprintf(x, sizeof x, f, j.at(k).get<double>());
    return std::string(x);
  };
  const auto v = [&](const char* k, const char* f = "%.6g") { return num(e, k, f); };
  const auto r = [&](const char* k) { return rebuilt ? " (" + num(*rebuilt, k, "%.6g") + ")" : std::string(); };
  return case_name + " | " + variant + " | " + code + " | " + v("initial") + " | " + v("kinetic") + r("kinetic") + " | " +
         v("elastic") + r("elastic") + " | " + v("dissipated") + r("dissipated") + " | " + v("balance", "%.3g") +
         r("balance") + " | " + v("max_abs_relative_drift", "%.3g");
}

/// The scatter of every between_codes quantity over silodem's further realisations of variant `i`
/// (seed_scatter.hpp), from their runs' folders `dirs` (in pc.seeds order; a failed one is an error row, and no scatter).
std::vector<CheckRow> seed_scatter(const PreparedCompare& pc, std::size_t i, const std::vector<silodem::CaseConfig>& cfgs,
                                   const std::vector<fs::path>& dirs, const std::vector<std::optional<std::string>>& failures,
                                   const std::vector<CheckRow>& main_rows, VerifyOutcome& out) {
  std::vector<std::vector<CheckRow>> per_seed;
  std::string label = "seeds " + std::to_string(pc.seed);
  for (std::size_t k = 0; k < pc.seeds.size(); ++k) {
    const std::string code = "silodem seed " + std::to_string(pc.seeds[k]);
    label += ", " + std::to_string(pc.seeds[k]);
    std::string failure = failures[k].value_or("");
    if (failure.empty()) {
      try {
        const ResultSet rs = read_result(dirs[k]);
        per_seed.push_back(run_checks(pc.checks, RunContext{cfgs[k], rs, pc.variants[i].label, code}));
        continue;
      } catch (const std::exception& e) {
        failure = e.what();
      }
    }
    out.rows.push_back(failed_run_row(pc.name, pc.variants[i].label, code, "the seed-scatter run failed: " + failure));
    return {};
  }
  std::vector<ScatterQuantity> qs;
  for (const auto& b : pc.between)
    qs.push_back({b.quantity, b.absolute              ? DifferenceScale::Absolute
                              : b.relative_to_largest ? DifferenceScale::LargestOfProfile
                                                      : DifferenceScale::Value});
  return seed_scatter_rows(qs, main_rows, per_seed, label);
}

/// silodem's rows from its dump frames (its reconstructed/), where a reference code's come from:
/// its own probes see every step and its last one, a code's rebuilt result only the frames, the
/// last of them up to one dump interval before the end. Empty without a dump.
std::vector<CheckRow> rows_at_frames(const PreparedCompare& pc, const silodem::CaseConfig& cfg, const std::string& variant,
                                     const fs::path& dir) {
  if (!fs::exists(dir / "reconstructed" / "summary.json")) return {};
  return run_checks(pc.checks, RunContext{cfg, read_result(dir / "reconstructed"), variant, "silodem"});
}

std::vector<std::string> known_codes() {
  std::vector<std::string> known;
  for (const auto& b : all_backends()) known.push_back(b->code());
  return known;
}

/// The lead run that makes a case's shared state: the case as written (`seed` < 0) or with
/// seeds[seed], at the compared runs' step (a continuation keeps the step), exactly to
/// from_state_at (the stop tests could end it earlier), without dumps.
silodem::CaseConfig lead_config(const PreparedCompare& pc, int seed) {
  silodem::CaseConfig lead = seed < 0 ? *pc.lead : pc.seed_leads[std::size_t(seed)];
  lead.dt = pc.configs.front().dt;
  lead.duration = pc.from_state_at;
  lead.dump_interval_steps = 0;
  lead.equilibrium.enabled = false;
  return lead;
}

/// Variant i as a run starts it: from the shared state `from_state` (state.sds) where the case has
/// one, else the case as patched (with seeds[seed] for a seed-scatter run of approach (a)).
silodem::CaseConfig run_config(const PreparedCompare& pc, std::size_t i, int seed, const fs::path& from_state) {
  if (!from_state.empty()) return silodem::continuation(pc.configs[i], silodem::read_state(from_state));
  return seed < 0 ? pc.configs[i] : pc.seed_configs[std::size_t(seed)][i];
}

std::size_t variant_index(const PreparedCompare& pc, const std::string& label) {
  for (std::size_t i = 0; i < pc.variants.size(); ++i)
    if (pc.variants[i].label == label) return i;
  throw std::runtime_error("the case has no compare variant " + label);
}

/// What a job's result depends on, for a resumed compare: the case as its runs read it (run_inputs.hpp:
/// not its judging), the job's own fields and the reference codes' ranks. The silodem build and the
/// codes' versions are not in it.
json job_inputs(const SweepPlan& plan, const SweepJob& job, const std::string& run_digest) {
  return {{"case_file", job.case_file.string()}, {"run_digest", run_digest}, {"kind", job.kind},
          {"code", job.code}, {"variant", job.variant}, {"seed", job.seed}, {"out_dir", job.out_dir.string()},
          {"from_state", job.from_state.string()}, {"ranks", plan.ranks}, {"launcher", plan.launcher}};
}

/// Runs the listed jobs (with `resume`, only those not complete from the same inputs) and returns
/// each one's failure (nullopt: done), by job index.
std::map<std::size_t, std::optional<std::string>> run_jobs(const SweepPlan& plan, const std::vector<std::size_t>& jobs,
                                                           const CompareOptions& opt, const char* round) {
  write_plan(plan, opt.silodem_binary);
  std::vector<std::size_t> pending;
  for (const std::size_t k : jobs)
    if (!(opt.resume && compare_job_complete(plan, k))) pending.push_back(k);
  if (opt.progress)
    std::fprintf(stderr, "[compare] %s: %zu runs (%zu kept from an earlier sweep) in %s\n", round, pending.size(),
                 jobs.size() - pending.size(),
                 opt.executor ? opt.executor->name().c_str() : "this process, one after another");
  (opt.executor ? *opt.executor : *in_process_executor()).run(plan, pending);
  std::map<std::size_t, std::optional<std::string>> failures;
  for (const std::size_t k : jobs) failures[k] = job_failure(plan, k);
  return failures;
}

}  // namespace

std::size_t validate_comparison(const fs::path& case_file) {
  std::vector<std::string> known;
  for (const auto& b : all_backends()) known.push_back(b->code());
  const PreparedCompare pc = prepare_compare(case_file, known);
  return pc.has_compare ? pc.variants.size() : 0;
}

std::string run_compare_job(const SweepJob& job, const Parallel& parallel, double progress_every) {
  const PreparedCompare pc = prepare_compare(job.case_file, known_codes());
  if (job.kind == "state") {
    silodem::RunOptions run{job.out_dir, progress_every >= 0.0, false};
    run.progress_every = std::max(0.0, progress_every);
    silodem::run_case(lead_config(pc, job.seed), run);
    return "";
  }
  const std::size_t i = variant_index(pc, job.variant);
  const silodem::CaseConfig cfg = run_config(pc, i, job.kind == "seed_run" ? job.seed : -1, job.from_state);
  for (const auto& be : all_backends()) {
    if (be->code() != job.code) continue;
    if (std::string why = be->set_parallel(parallel); !why.empty()) return why;
    be->set_progress_every(progress_every);
    const BackendResult br = be->run(cfg, job.out_dir, pc.time_limit);
    return br.status == BackendResult::Status::Ran ? "" : br.reason;
  }
  return "unknown code " + job.code;
}

namespace {

/// What compare decided for one code of one variant: a row already (skipped, or failed before it
/// ran) or the job that runs it.
struct CodeRun {
  std::string code;
  std::optional<CheckRow> row;
  std::size_t job = 0;
};

struct VariantRuns {
  std::optional<CheckRow> failed;  // the variant could not start (no shared state, or no continuation)
  silodem::CaseConfig cfg;
  std::vector<CodeRun> codes;
  std::vector<std::size_t> seed_jobs;  // in pc.seeds order
  std::vector<silodem::CaseConfig> seed_cfgs;
};

}  // namespace

VerifyOutcome compare_cases(const std::vector<fs::path>& case_files, const CompareOptions& opt_in) {
  CompareOptions opt = opt_in;
  opt.out_root = fs::absolute(opt.out_root);
  const auto backends = all_backends();
  const std::vector<std::string> known = known_codes();
  for (const auto& c : opt.codes)
    if (std::find(known.begin(), known.end(), c) == known.end())
      throw silodem::CaseError("--codes", "unknown code \"" + c + "\"");
  std::vector<PreparedCompare> cases;
  std::vector<std::string> names;
  for (const auto& f : case_files) {
    cases.push_back(prepare_compare(f, known));  // all input checked first
    cases.back().file = fs::absolute(f);
    names.push_back(cases.back().name);
  }
  require_distinct_case_names(case_files, names);
  std::map<std::string, std::string> run_digests;  // by case: what its runs read (run_inputs.hpp)
  for (const auto& pc : cases) run_digests[pc.name] = run_digest(pc.file);
  std::map<std::string, std::string> cannot_run_parallel;  // by code
  for (const auto& be : backends)
    if (std::string why = be->set_parallel(opt.parallel); !why.empty()) cannot_run_parallel[be->code()] = why;
  if (opt.before_first_run) opt.before_first_run();

  // The runs are jobs (sweep/job_plan.hpp) in two rounds: the shared states (approach (b) of the
  // silo issue: one filled state, exported by silodem, for every code and variant, so differences
  // after it come from integration and contact law, not from the packing), then every code's run
  // of every variant and silodem's seed-scatter runs, which continue from those states.
  SweepPlan plan{opt.out_root / "sweep", {}, opt.parallel.ranks, opt.parallel.launcher};
  const auto state_file = [&](const PreparedCompare& pc, int seed) {
    return opt.out_root / pc.name / (seed < 0 ? "shared_state" : "shared_state_seed" + std::to_string(pc.seeds[std::size_t(seed)]));
  };
  std::vector<std::size_t> first_round;
  std::map<std::string, std::vector<std::size_t>> state_jobs;  // by case: the own seed's, then seeds[k]'s
  for (const auto& pc : cases) {
    if (!pc.has_compare || !(pc.from_state_at > 0.0)) continue;
    for (int seed = -1; seed < int(pc.seeds.size()); ++seed) {
      if (opt.progress)
        std::fprintf(stderr, "[compare] %s: silodem (the case as written, seed %llu) to t = %g s for the shared state\n",
                     pc.name.c_str(), (unsigned long long)(seed < 0 ? pc.seed : pc.seeds[std::size_t(seed)]), pc.from_state_at);
      state_jobs[pc.name].push_back(plan.jobs.size());
      first_round.push_back(plan.jobs.size());
      plan.jobs.push_back({pc.file, pc.name, "", state_file(pc, seed), "state", "silodem", seed, {}});
      plan.jobs.back().inputs = job_inputs(plan, plan.jobs.back(), run_digests.at(pc.name));
      plan.jobs.back().expected_work = expected_work(lead_config(pc, seed), "silodem");
    }
  }
  const auto state_failures = run_jobs(plan, first_round, opt, "the shared states");

  std::vector<std::size_t> second_round;
  std::map<std::string, std::vector<VariantRuns>> runs;  // by case, per variant
  std::map<std::string, std::optional<CheckRow>> case_failed;
  for (const auto& pc : cases) {
    if (!pc.has_compare) continue;
    for (const std::size_t k : state_jobs[pc.name])
      if (const auto& why = state_failures.at(k)) {
        case_failed[pc.name] = failed_run_row(pc.name, "all", "all", "the shared state could not be made: " + *why);
        break;
      }
    if (case_failed[pc.name]) continue;
    const bool shared = pc.from_state_at > 0.0;
    for (std::size_t i = 0; i < pc.variants.size(); ++i) {
      const auto& var = pc.variants[i];
      const std::string dir_label = variant_dir_name(var);
      VariantRuns vr;
      const fs::path from = shared ? state_file(pc, -1) / "state.sds" : fs::path();
      try {
        vr.cfg = run_config(pc, i, -1, from);
      } catch (const std::exception& e) {
        vr.failed = failed_run_row(pc.name, var.label, "all", std::string("cannot continue from the shared state: ") + e.what());
        runs[pc.name].push_back(std::move(vr));
        continue;
      }
      for (const auto& be : backends) {
        const std::string code = be->code();
        if (std::find(pc.codes.begin(), pc.codes.end(), code) == pc.codes.end()) continue;
        CodeRun cr{code, std::nullopt, 0};
        const auto skipped = [&]() -> std::string {  // why this code does not run the variant ("": it does)
          if (const auto it = pc.left_out.find(code); it != pc.left_out.end()) return "left out by the case: " + it->second;
          // Left out on request: a skip row, so a report of fewer codes never reads as complete.
          if (!opt.codes.empty() && std::find(opt.codes.begin(), opt.codes.end(), code) == opt.codes.end())
            return "skipped: not requested (--codes)";
          if (const std::string why = be->missing(); !why.empty()) return "skipped: " + why;
          if (const auto it = cannot_run_parallel.find(code); it != cannot_run_parallel.end())
            return "skipped: not on " + std::to_string(opt.parallel.ranks) + " ranks: " + it->second;
          if (const std::string why = be->not_representable(vr.cfg); !why.empty()) return "not representable: " + why;
          return "";
        };
        if (const std::string why = skipped(); !why.empty())
          cr.row = skip_row(pc.name, var.label, code, why);
        else {
          cr.job = plan.jobs.size();
          second_round.push_back(cr.job);
          plan.jobs.push_back({pc.file, pc.name, var.label, opt.out_root / pc.name / dir_label / code, "run", code, -1, from});
          plan.jobs.back().inputs = job_inputs(plan, plan.jobs.back(), run_digests.at(pc.name));
          plan.jobs.back().expected_work = expected_work(vr.cfg, code);
        }
        const bool ours = code == "silodem" && !cr.row;
        vr.codes.push_back(std::move(cr));
        if (!ours) continue;
        // silodem with the other seeds — from their shared states (b), or whole runs (a).
        for (std::size_t k = 0; k < pc.seeds.size(); ++k) {
          const fs::path seed_from = shared ? state_file(pc, int(k)) / "state.sds" : fs::path();
          vr.seed_jobs.push_back(plan.jobs.size());
          second_round.push_back(plan.jobs.size());
          plan.jobs.push_back({pc.file, pc.name, var.label,
                               opt.out_root / pc.name / dir_label / ("silodem_seed" + std::to_string(pc.seeds[k])), "seed_run",
                               "silodem", int(k), seed_from});
          plan.jobs.back().inputs = job_inputs(plan, plan.jobs.back(), run_digests.at(pc.name));
          plan.jobs.back().expected_work = expected_work(vr.cfg, "silodem");
        }
      }
      runs[pc.name].push_back(std::move(vr));
    }
  }
  const auto run_failures = run_jobs(plan, second_round, opt, "every code's runs");

  VerifyOutcome out;
  for (const auto& pc : cases) {
    if (!pc.has_compare) {
      out.rows.push_back(skip_row(pc.name, "base", "all", "the case has no \"compare\" section (verify only)"));
      continue;
    }
    if (case_failed[pc.name]) {
      out.rows.push_back(*case_failed[pc.name]);
      continue;
    }
    for (std::size_t i = 0; i < pc.variants.size(); ++i) {
      const auto& var = pc.variants[i];
      VariantRuns& vr = runs[pc.name][i];
      if (vr.failed) {
        out.rows.push_back(*vr.failed);
        continue;
      }
      const silodem::CaseConfig& cfg = vr.cfg;
      std::map<std::string, std::vector<CheckRow>> by_code;
      std::vector<CheckRow> silodem_at_frames;
      for (const CodeRun& cr : vr.codes) {
        const std::string& code = cr.code;
        if (cr.row) {
          out.rows.push_back(*cr.row);
          continue;
        }
        if (const auto& why = run_failures.at(cr.job)) {
          // A crash or time-out is an error, not a skip.
          out.rows.push_back(failed_run_row(pc.name, var.label, code, code + " failed: " + *why));
          continue;
        }
        const fs::path dir = plan.jobs[cr.job].out_dir;
        const ResultSet rs = read_result(dir);
        const double secs = rs.summary.at("run").value("wall_seconds", 0.0);
        out.run_seconds.emplace_back(pc.name + " " + var.label + " " + code, secs);
        const auto rows = run_checks(pc.checks, RunContext{cfg, rs, var.label, code});
        by_code[code].insert(by_code[code].end(), rows.begin(), rows.end());
        if (code == "silodem" && std::any_of(pc.between.begin(), pc.between.end(), [](const Between& b) { return b.at_frames; }))
          silodem_at_frames = rows_at_frames(pc, cfg, var.label, dir);
        // silodem: its own ledger against the rebuild from its dump (the reference codes get only that).
        std::optional<json> rebuilt;
        if (code == "silodem" && fs::exists(dir / "reconstructed" / "summary.json")) {
          rebuilt = read_result(dir / "reconstructed").summary.at("energy");
          if (pc.ledger_tolerance > 0.0) {
            const json& own = rs.summary.at("energy");
            for (const char* term : {"kinetic", "dissipated"}) {
              CheckRow r;
              r.case_name = pc.name;
              r.variant = var.label;
              r.code = "silodem";
              r.quantity = std::string("ledger_vs_rebuilt_") + term;
              r.subject = "final";
              r.expected = (*rebuilt)[term];
              r.measured = own[term];
              const double scale = std::max(std::abs(own["scale"].get<double>()), 1e-300);
              r.error = (r.measured - r.expected) / scale;
              r.kind = RowKind::Match;
              r.tolerance = pc.ledger_tolerance;
              r.tolerance_source = pc.ledger_source;
              judge(r);
              r.note = "difference / energy moved";
              by_code[code].push_back(r);
            }
          }
        }
        out.ledgers.push_back(ledger_line(pc.name, var.label, code, rs.summary.at("energy"), rebuilt ? &*rebuilt : nullptr));
      }
      for (auto& [code, rows] : by_code) out.rows.insert(out.rows.end(), rows.begin(), rows.end());
      // Between codes: every reference code against silodem, subject by subject.
      if (!by_code.count("silodem")) continue;
      std::vector<CheckRow> scatter;
      if (!pc.seeds.empty()) {
        std::vector<fs::path> dirs;
        std::vector<std::optional<std::string>> failures;
        for (const std::size_t k : vr.seed_jobs) dirs.push_back(plan.jobs[k].out_dir), failures.push_back(run_failures.at(k));
        for (std::size_t k = 0; k < pc.seeds.size(); ++k)
          vr.seed_cfgs.push_back(run_config(pc, i, int(k), plan.jobs[vr.seed_jobs[k]].from_state));
        scatter = seed_scatter(pc, i, vr.seed_cfgs, dirs, failures, by_code["silodem"], out);
      }
      out.rows.insert(out.rows.end(), scatter.begin(), scatter.end());
      std::vector<CheckRow> between_rows;
      std::map<std::string, const CheckRow*> ours, ours_at_frames, ours_mean;
      for (const auto& r : by_code["silodem"]) ours[r.quantity + "|" + r.subject] = &r;
      for (const auto& r : silodem_at_frames) ours_at_frames[r.quantity + "|" + r.subject] = &r;
      std::vector<CheckRow> means = scatter;  // a scatter row's expected is the mean of the realisations
      for (auto& r : means) r.measured = r.expected;
      for (const auto& r : means) ours_mean[r.quantity + "|" + r.subject] = &r;
      for (const auto& [code, rows] : by_code) {
        if (code == "silodem") continue;
        for (const auto& bq : pc.between) {
          if (!bq.codes.empty() && std::find(bq.codes.begin(), bq.codes.end(), code) == bq.codes.end()) continue;
          if (!bq.variants.empty() && std::find(bq.variants.begin(), bq.variants.end(), var.label) == bq.variants.end()) continue;
          std::map<std::string, double> largest;  // per profile, of the reference code's values
          for (const auto& r : rows)
            if (r.quantity == bq.quantity)
              largest[profile_of(r.subject)] = std::max(largest[profile_of(r.subject)], std::abs(r.measured));
          // Without a dump every code dumped every step, so silodem's own rows sample as theirs do.
          const bool at_frames = bq.at_frames && !silodem_at_frames.empty();
          const auto& mine = bq.seeds_mean ? ours_mean : at_frames ? ours_at_frames : ours;
          for (const auto& r : rows) {
            if (r.quantity != bq.quantity) continue;
            const auto it = mine.find(r.quantity + "|" + r.subject);
            if (it == mine.end()) continue;
            between_rows.push_back(between_row(bq, pc.name, var.label, code, r, *it->second, largest[profile_of(r.subject)]));
            std::string& note = between_rows.back().note;
            if (at_frames) note += std::string(note.empty() ? "" : "; ") + "silodem at the dump frames, as the reference code";
            if (bq.seeds_mean)
              note += std::string(note.empty() ? "" : "; ") + "silodem: the mean of its " +
                      std::to_string(pc.seeds.size() + 1) + " realisations";
          }
        }
      }
      annotate_with_scatter(between_rows, scatter);
      out.rows.insert(out.rows.end(), between_rows.begin(), between_rows.end());
    }
  }
  return out;
}

}  // namespace harness
