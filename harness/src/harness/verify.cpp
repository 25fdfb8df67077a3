#include "harness/verify.hpp"

#include <algorithm>
#include <set>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "harness/case_names.hpp"
#include "harness/janssen_prediction.hpp"
#include "harness/taken_rows.hpp"
#include "harness/variants.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/case/json_reader.hpp"
#include "silodem/run/simulation.hpp"

namespace harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct PreparedCase {
  fs::path file;  // absolute
  std::string name;
  json checks;
  std::vector<Variant> variants;
  std::vector<silodem::CaseConfig> configs;
};

PreparedCase prepare(const fs::path& file) {
  const json j = silodem::read_case_json(file);
  PreparedCase pc;
  pc.file = fs::absolute(file);
  try {
    const silodem::CaseConfig base = silodem::load_case(j);
    pc.name = base.name;
    if (base.verify.is_null()) throw silodem::CaseError("$.verify", "the case has no checks to verify");
    const silodem::JsonReader v(base.verify, "$.verify");
    if (v.has("variants")) (void)v.raw("variants");  // expanded below
    pc.checks = v.array("checks");
    if (pc.checks.empty()) v.fail("checks", "must list at least one check");
    v.finish();
    pc.variants = expand_variants(j);
    const std::vector<std::string> axes = variant_axes(pc.variants);
    for (const auto& var : pc.variants) {
      pc.configs.push_back(load_variant(var, "variant"));
      for (std::size_t i = 0; i < pc.checks.size(); ++i)
        validate_check(pc.checks[i], "$.verify.checks[" + std::to_string(i) + "]", pc.configs.back(), axes);
    }
  } catch (const silodem::CaseError& e) {
    throw silodem::CaseError(file.string() + " " + e.path(), std::string(e.what()).substr(e.path().size() + 2));
  }
  return pc;
}

/// The cases a case's checks take rows from (janssen_prediction: its material tests).
std::vector<std::string> cases_taken(const PreparedCase& pc) {
  std::vector<std::string> out;
  for (const auto& c : pc.checks)
    for (auto& name : cases_a_check_takes(c)) out.push_back(std::move(name));
  return out;
}

/// The cases with every case a check takes before it (otherwise in the order given); a case taken
/// but neither given nor in the earlier rows is refused before anything runs.
std::vector<PreparedCase> in_dependency_order(std::vector<PreparedCase> cases, const std::vector<fs::path>& files,
                                              const std::vector<CheckRow>& taken) {
  const auto measured_before = [&](const std::string& name) {
    return std::any_of(taken.begin(), taken.end(), [&](const CheckRow& r) { return r.case_name == name; });
  };
  std::set<std::string> given;
  for (const auto& c : cases) given.insert(c.name);
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (const auto& name : cases_taken(cases[i])) {
      if (!given.count(name) && !measured_before(name))
        throw silodem::CaseError(files[i].string() + " $.verify.checks",
                                 "takes the material test of case \"" + name + "\", which this command does not run: "
                                 "give its file too (verify runs it first), or --material-tests-from an earlier "
                                 "verify's verdicts.json that has it");
    }
  std::vector<PreparedCase> ordered;
  std::vector<bool> placed(cases.size(), false);
  while (ordered.size() < cases.size()) {
    bool progress = false;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (placed[i]) continue;
      const auto needs = cases_taken(cases[i]);
      const bool ready = std::all_of(needs.begin(), needs.end(), [&](const std::string& n) {
        return !given.count(n) || std::any_of(ordered.begin(), ordered.end(), [&](const PreparedCase& c) { return c.name == n; });
      });
      if (ready) ordered.push_back(std::move(cases[i])), placed[i] = true, progress = true;
    }
    if (!progress) throw silodem::CaseError("$.verify.checks", "the cases take each other's material tests in a cycle");
  }
  return ordered;
}

}  // namespace

std::size_t validate_verification(const fs::path& case_file) { return prepare(case_file).variants.size(); }

json verify_variant_json(const fs::path& case_file, const std::string& label) {
  for (const auto& var : prepare(case_file).variants)
    if (var.label == label) return var.case_json;
  throw silodem::CaseError(case_file.string() + " $.verify.variants", "has no variant " + label);
}

namespace {

/// Every case variant a job of the plan, in the order verify judges them.
SweepPlan plan_of(const std::vector<PreparedCase>& cases, const fs::path& out_root) {
  SweepPlan plan{out_root / "sweep", {}};
  for (const auto& pc : cases)
    for (std::size_t i = 0; i < pc.variants.size(); ++i) {
      plan.jobs.push_back({pc.file, pc.name, pc.variants[i].label, out_root / pc.name / variant_dir_name(pc.variants[i])});
      plan.jobs.back().expected_work = expected_work(pc.configs[i], "silodem");
    }
  return plan;
}

}  // namespace

VerifyOutcome verify_cases(const std::vector<fs::path>& case_files, const VerifyOptions& opt) {
  std::vector<PreparedCase> cases;
  std::vector<std::string> names;
  for (const auto& f : case_files) {
    cases.push_back(prepare(f));  // all input checked before any run
    names.push_back(cases.back().name);
  }
  require_distinct_case_names(case_files, names);
  // Rows the checks may take: the earlier verify's material tests, then this run's as they come.
  std::vector<CheckRow> taken = opt.material_tests_from ? read_spread_rows(*opt.material_tests_from) : std::vector<CheckRow>{};
  cases = in_dependency_order(std::move(cases), case_files, taken);
  if (opt.before_first_run) opt.before_first_run();

  // Every run is an independent job (sweep/job_plan.hpp): all run first, by the executor asked for,
  // then the results are read and judged case by case.
  const SweepPlan plan = plan_of(cases, fs::absolute(opt.out_root));
  write_plan(plan, opt.silodem_binary);
  std::vector<std::size_t> pending;
  for (std::size_t k = 0; k < plan.jobs.size(); ++k)
    if (!(opt.resume && job_complete(plan, k))) pending.push_back(k);
  if (opt.progress)
    std::fprintf(stderr, "[verify] %zu runs (%zu kept from an earlier sweep) in %s\n", pending.size(),
                 plan.jobs.size() - pending.size(), opt.executor ? opt.executor->name().c_str() : "this process");
  (opt.executor ? *opt.executor : *in_process_executor()).run(plan, pending);
  const std::set<std::size_t> ran(pending.begin(), pending.end());

  VerifyOutcome out;
  std::size_t job = 0;
  for (const auto& pc : cases) {
    std::vector<CheckRow> case_rows;
    std::vector<std::pair<std::string, std::string>> groups;
    std::vector<double> dts;
    bool all_ran = true;
    for (std::size_t i = 0; i < pc.variants.size(); ++i, ++job) {
      const auto& var = pc.variants[i];
      const auto& cfg = pc.configs[i];
      if (ran.count(job))
        if (const auto why = job_failure(plan, job)) {
          case_rows.push_back(failed_run_row(pc.name, var.label, "silodem", "the run failed: " + *why));
          all_ran = false;
          continue;
        }
      const ResultSet rs = read_result(plan.jobs[job].out_dir);
      out.run_seconds.emplace_back(pc.name + " " + var.label, rs.summary["run"]["wall_seconds"].get<double>());
      const auto rows = run_checks(pc.checks, RunContext{cfg, rs, var.label, "silodem", &taken});
      case_rows.insert(case_rows.end(), rows.begin(), rows.end());
      groups.emplace_back(var.label, label_without(var, ""));
      dts.push_back(cfg.dt);
    }
    for (const auto& check : pc.checks) {
      if (!all_ran) break;  // the checks across variants need every variant's rows
      if (check.at("type") == "beverloo_fit") {
        std::vector<std::string> labels;
        std::vector<double> outlets;
        for (std::size_t i = 0; i < pc.variants.size(); ++i) {
          labels.push_back(pc.variants[i].label);
          outlets.push_back(outlet_diameter(check, pc.configs[i]));
        }
        auto rows = beverloo_fit_rows(check, pc.name, case_rows, labels, outlets, pc.configs[0].gravity.norm(),
                                       frictional_grains(pc.configs[0]));
        case_rows.insert(case_rows.end(), rows.begin(), rows.end());
      }
      if (check.at("type") == "spread") {
        std::vector<std::pair<std::string, std::string>> by_axis;
        for (const auto& var : pc.variants) by_axis.emplace_back(var.label, label_without(var, check.at("axis")));
        auto rows = spread_rows(check, pc.name, case_rows, by_axis);
        case_rows.insert(case_rows.end(), rows.begin(), rows.end());
      }
      if (check.at("type") != "convergence") continue;
      const std::string axis = check.at("axis");
      for (std::size_t i = 0; i < groups.size(); ++i) groups[i].second = label_without(pc.variants[i], axis);
      auto rows = convergence_rows(check, pc.name, case_rows, groups, dts);
      case_rows.insert(case_rows.end(), rows.begin(), rows.end());
    }
    out.rows.insert(out.rows.end(), case_rows.begin(), case_rows.end());
    taken.insert(taken.end(), case_rows.begin(), case_rows.end());
  }
  return out;
}

}  // namespace harness
