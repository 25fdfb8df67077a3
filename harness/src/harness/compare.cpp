#include "harness/compare.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <algorithm>
#include <optional>
#include <sstream>

#include "harness/backends/backend.hpp"
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

struct Between {
  std::string quantity;
  double tolerance;
  bool relative_to_largest = false;  // error relative to the largest value of the profile, not each value
  bool absolute = false;             // plain difference (values already dimensionless, e.g. energy fractions)
  std::string source;                // where the tolerance comes from ("": none, the rows report)
  std::vector<std::string> codes;    // the reference codes it applies to (empty: all)
  std::string report;                // why these codes' differences are reported, not judged ("": judged)
  std::vector<std::string> variants;  // the compare variants it applies to, by label ("run=a"; empty: all)
};


struct PreparedCompare {
  std::string name;
  bool has_compare = true;  // a verify-only case is reported as skipped, not refused
  json checks;
  std::vector<Between> between;
  double ledger_tolerance = 0.0;
  std::string ledger_source;
  double time_limit = 600.0;
  double from_state_at = 0.0;  // > 0: every code starts from the state silodem reaches at this time
  std::optional<silodem::CaseConfig> lead;  // the case as written (silodem's own protocol) that makes that state
  std::uint64_t seed = 0;                   // the case's own
  std::vector<std::uint64_t> seeds;         // further realisations, silodem only (seed scatter)
  std::vector<silodem::CaseConfig> seed_leads;                  // (b): the shared state with each seed
  std::vector<std::vector<silodem::CaseConfig>> seed_configs;  // (a): [seed][variant], the whole run with each seed
  std::vector<std::string> codes;
  std::map<std::string, std::string> left_out;  // code -> why the case does not run it (a skip row)
  std::vector<Variant> variants;
  std::vector<silodem::CaseConfig> configs;
};

/// The reference codes' ledgers are rebuilt from dump frames (trace/reconstruct.cpp), which
/// integrate the dashpot power frame to frame: with fewer than two frames in the shortest contact,
/// a contact's work can fall between them and the rebuilt balance says nothing (a 1000-step dump
/// gave a drift of 1.71 in every code). Such an energy_balance is refused before anything runs.
void refuse_unresolved_ledger(const silodem::CaseConfig& cfg, const std::string& path, const std::string& variant) {
  const double frames = energy_frames_per_contact(cfg);
  if (frames >= 2.0) return;
  const long every = std::max(1L, cfg.dump_interval_steps);
  const long most = std::max(1L, long(std::floor(frames * double(every) / 2.0)));
  char b[400];
  std::snprintf(b, sizeof b,
                "energy_balance of ledgers rebuilt from dumps every %ld steps cannot integrate the dashpot work: the "
                "shortest contact spans %.3g frames (fewer than 2), so its work can fall between frames; dump at most "
                "every %ld steps (output.dump_interval_steps) or drop the check (in compare variant %s)",
                every, frames, most, variant.c_str());
  throw silodem::CaseError(path, b);
}

PreparedCompare prepare(const fs::path& file, const std::vector<std::string>& known_codes) {
  json j = silodem::read_case_json(file);
  PreparedCompare pc;
  try {
    const silodem::CaseConfig base = silodem::load_case(j);
    pc.name = base.name;
    if (!j.contains("compare")) {
      pc.has_compare = false;
      return pc;
    }
    const silodem::JsonReader c(j["compare"], "$.compare");
    // The shared state is made by the case as written — the protocol its verify run uses — before
    // any compare patch: the packing is silodem's; the codes are compared on what follows.
    if (j["compare"].contains("from_state_at")) pc.lead = silodem::load_case(j);
    pc.seed = base.seed;
    if (c.has("seeds")) {
      const json& ss = c.array("seeds");
      if (ss.empty()) c.fail("seeds", "must not be empty (omit it for no seed scatter)");
      for (std::size_t i = 0; i < ss.size(); ++i) {
        const std::string path = c.child_path("seeds") + "[" + std::to_string(i) + "]";
        if (!ss[i].is_number_unsigned()) throw silodem::CaseError(path, "a seed is an integer >= 0");
        const std::uint64_t seed = ss[i].get<std::uint64_t>();
        if (seed == pc.seed || std::find(pc.seeds.begin(), pc.seeds.end(), seed) != pc.seeds.end())
          throw silodem::CaseError(path, "seed " + std::to_string(seed) + " repeats the case's seed or another in the list");
        pc.seeds.push_back(seed);
        if (pc.lead) {
          json js = j;
          js["seed"] = seed;
          pc.seed_leads.push_back(silodem::load_case(js));
        }
      }
    }
    // "base": a merge patch every compared run starts from (e.g. the integrator all codes share).
    if (c.has("base")) {
      const json& patch = c.raw("base");
      if (!patch.is_object() || patch.contains("verify") || patch.contains("compare"))
        c.fail("base", "must be a merge patch object that leaves verify/compare alone");
      j.merge_patch(patch);
    }
    if (c.has("variants")) (void)c.raw("variants");
    pc.checks = c.array("checks");
    if (pc.checks.empty()) c.fail("checks", "must list at least one check");
    for (std::size_t i = 0; i < pc.checks.size(); ++i)
      if (pc.checks[i].is_object() && pc.checks[i].value("type", "") == "convergence")
        throw silodem::CaseError(c.child_path("checks") + "[" + std::to_string(i) + "]",
                                 "convergence checks belong in \"verify\" (compare runs one time step per variant)");
    pc.time_limit = c.number_or("time_limit_s", 600.0);
    if (!(pc.time_limit > 0.0)) c.fail("time_limit_s", "must be > 0");
    pc.codes = known_codes;
    if (c.has("codes")) {
      pc.codes.clear();
      const json& cs = c.array("codes");
      for (std::size_t i = 0; i < cs.size(); ++i) {
        if (!cs[i].is_string() || std::find(known_codes.begin(), known_codes.end(), cs[i].get<std::string>()) == known_codes.end())
          throw silodem::CaseError(c.child_path("codes") + "[" + std::to_string(i) + "]", "unknown code");
        pc.codes.push_back(cs[i]);
      }
    }
    if (c.has("left_out")) {
      // A code this case does not run, and why (e.g. the hours it would take): a skip row that says so.
      const silodem::JsonReader lo = c.object("left_out");
      for (const auto& [code, why] : c.raw("left_out").items()) {
        if (code == "silodem" || std::find(known_codes.begin(), known_codes.end(), code) == known_codes.end())
          lo.fail(code, "not a reference code");
        if (!why.is_string() || why.get<std::string>().find_first_not_of(" \t\n") == std::string::npos)
          lo.fail(code, "say why the case leaves this code out");
        pc.left_out[code] = why.get<std::string>();
      }
    }
    if (c.has("between_codes")) {
      const json& bs = c.array("between_codes");
      for (std::size_t i = 0; i < bs.size(); ++i) {
        const silodem::JsonReader b(bs[i], c.child_path("between_codes") + "[" + std::to_string(i) + "]");
        // "report": the codes run another algorithm (stated there), so their difference is a measured figure.
        Between x{b.string("quantity"), b.has("report") ? b.number_or("tolerance", 0.0) : b.number("tolerance")};
        x.report = b.string_or("report", "");
        if (b.has("report") && x.report.empty()) b.fail("report", "must say why the difference is not judged");
        if (x.report.empty() && !(x.tolerance > 0.0)) b.fail("tolerance", "must be > 0");
        if (b.has("codes")) {
          const json& cs = b.array("codes");
          for (std::size_t k = 0; k < cs.size(); ++k) {
            if (!cs[k].is_string() || cs[k] == "silodem" ||
                std::find(known_codes.begin(), known_codes.end(), cs[k].get<std::string>()) == known_codes.end())
              throw silodem::CaseError(b.child_path("codes") + "[" + std::to_string(k) + "]", "not a reference code");
            x.codes.push_back(cs[k]);
          }
        }
        if (b.has("variants")) {
          const json& vs = b.array("variants");
          for (std::size_t k = 0; k < vs.size(); ++k) {
            if (!vs[k].is_string()) b.fail("variants", "a list of variant labels such as \"axis=value\"");
            x.variants.push_back(vs[k]);
          }
        }
        const std::string rel = b.choice_or("relative_to", {"value", "largest", "absolute"}, "value");
        x.relative_to_largest = rel == "largest";
        x.absolute = rel == "absolute";
        static const std::vector<std::string> known = {
            "restitution", "contact_duration", "escape_speed", "turning_gap", "cohesion_energy_removed",
            "drop_contact_height", "integrated_contact_height", "rebound_height", "energy_drift",
            "band_pressure", "mass_flow_rate", "closure_peak/pre_pressure", "closure_mean_post/pre_pressure", "wall_load/weight",
            "effective_wall_friction_mu_w", "lateral_pressure_ratio_K", "janssen_fit_r2", "energy_kinetic", "energy_elastic",
            "energy_gravitational_change", "energy_lost", "normal_restitution", "tangential_restitution", "rebound_spin",
            "rebound_angle", "hertz_max_overlap", "hertz_duration", "sliding_speed", "sliding_spin", "rolling_speed",
            "rolling_spin", "held_displacement", "slot_mass_rate", "drum_torque", "drum_power", "dynamic_angle_deg"};
        if (std::find(known.begin(), known.end(), x.quantity) == known.end())
          b.fail("quantity", "no check produces \"" + x.quantity + "\"");
        validate_tolerance_source(b, "tolerance");
        x.source = tolerance_source(bs[i], "tolerance", x.tolerance);
        b.finish();
        pc.between.push_back(x);
      }
    }
    pc.ledger_tolerance = c.number_or("ledger_reconstruction_tolerance", 0.0);
    validate_tolerance_source(c, "ledger_reconstruction_tolerance");
    pc.ledger_source = tolerance_source(j["compare"], "ledger_reconstruction_tolerance", pc.ledger_tolerance);
    pc.from_state_at = c.number_or("from_state_at", 0.0);
    if (pc.from_state_at < 0.0) c.fail("from_state_at", "must be >= 0 s");
    c.finish();
    pc.variants = expand_variants(j, "compare");
    for (std::size_t i = 0; i < pc.between.size(); ++i)
      for (const auto& label : pc.between[i].variants)
        if (std::none_of(pc.variants.begin(), pc.variants.end(), [&](const Variant& v) { return v.label == label; }))
          throw silodem::CaseError("$.compare.between_codes[" + std::to_string(i) + "].variants",
                                   "no compare variant \"" + label + "\"");
    std::vector<std::string> axes;
    for (const auto& [axis, value] : pc.variants.front().axes) axes.push_back(axis);
    for (const auto& var : pc.variants) {
      try {
        pc.configs.push_back(silodem::load_case(var.case_json));
      } catch (const silodem::CaseError& e) {
        throw silodem::CaseError(e.path(), std::string(e.what()).substr(e.path().size() + 2) + " (in compare variant " +
                                               var.label + ")");
      }
      for (std::size_t i = 0; i < pc.checks.size(); ++i) {
        validate_check(pc.checks[i], "$.compare.checks[" + std::to_string(i) + "]", pc.configs.back(), axes);
        if (!cases_a_check_takes(pc.checks[i]).empty())
          throw silodem::CaseError("$.compare.checks[" + std::to_string(i) + "]",
                                   "a check that takes other cases' material tests runs in verify only");
        if (pc.checks[i].value("type", "") == "energy_balance")
          refuse_unresolved_ledger(pc.configs.back(), "$.compare.checks[" + std::to_string(i) + "]", var.label);
      }
      if (pc.from_state_at > 0.0 && pc.configs.back().dt != pc.configs.front().dt)
        c.fail("from_state_at", "every variant must use the same time step to continue from one state (variant " +
                                    var.label + " differs)");
      if (pc.from_state_at >= pc.configs.back().duration)
        c.fail("from_state_at", "must come before the end of the run (" + std::to_string(pc.configs.back().duration) + " s)");
    }
    // Approach (a), no shared state: each further seed reruns every variant whole (other wall
    // roughness and drop draws, so another packing) — the scatter of silodem's own fills.
    if (!pc.lead)
      for (const std::uint64_t seed : pc.seeds) {
        pc.seed_configs.emplace_back();
        for (const auto& var : pc.variants) {
          json js = var.case_json;
          js["seed"] = seed;
          pc.seed_configs.back().push_back(silodem::load_case(js));
        }
      }
  } catch (const silodem::CaseError& e) {
    throw silodem::CaseError(file.string() + " " + e.path(), std::string(e.what()).substr(e.path().size() + 2));
  }
  return pc;
}

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

/// silodem with the other seeds — from their shared states (b), or whole runs (a) — variant `i`:
/// the scatter of every between_codes quantity over the realisations (seed_scatter.hpp). A failed run is an error row, and no scatter.
std::vector<CheckRow> seed_scatter(const PreparedCompare& pc, std::size_t i, const std::string& dir_label,
                                   const std::vector<silodem::StateSnapshot>& states, const std::vector<CheckRow>& main_rows,
                                   const CompareOptions& opt, VerifyOutcome& out) {
  const auto backends = all_backends();
  const Backend* ours = nullptr;
  for (const auto& b : backends)
    if (b->code() == "silodem") ours = b.get();
  std::vector<std::vector<CheckRow>> per_seed;
  std::string label = "seeds " + std::to_string(pc.seed);
  for (std::size_t k = 0; k < pc.seeds.size(); ++k) {
    const std::string code = "silodem seed " + std::to_string(pc.seeds[k]);
    label += ", " + std::to_string(pc.seeds[k]);
    if (opt.progress) std::fprintf(stderr, "[compare] %s %s: %s\n", pc.name.c_str(), pc.variants[i].label.c_str(), code.c_str());
    const fs::path dir = opt.out_root / pc.name / dir_label / ("silodem_seed" + std::to_string(pc.seeds[k]));
    std::string failure;
    try {
      const silodem::CaseConfig cfg =
          states.empty() ? pc.seed_configs[k][i] : silodem::continuation(pc.configs[i], states[k]);
      const BackendResult br = ours->run(cfg, dir, pc.time_limit);
      if (br.status == BackendResult::Status::Ran) {
        const ResultSet rs = read_result(dir);
        RunContext ctx{cfg, rs, pc.variants[i].label, code};
        std::vector<CheckRow> rows;
        for (const auto& check : pc.checks) {
          auto r = run_check(check, ctx);
          rows.insert(rows.end(), r.begin(), r.end());
        }
        per_seed.push_back(std::move(rows));
        continue;
      }
      failure = br.reason;
    } catch (const std::exception& e) {
      failure = e.what();
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

}  // namespace

std::size_t validate_comparison(const fs::path& case_file) {
  std::vector<std::string> known;
  for (const auto& b : all_backends()) known.push_back(b->code());
  const PreparedCompare pc = prepare(case_file, known);
  return pc.has_compare ? pc.variants.size() : 0;
}

VerifyOutcome compare_cases(const std::vector<fs::path>& case_files, const CompareOptions& opt_in) {
  CompareOptions opt = opt_in;
  opt.out_root = fs::absolute(opt.out_root);
  const auto backends = all_backends();
  std::vector<std::string> known;
  for (const auto& b : backends) known.push_back(b->code());
  for (const auto& c : opt.codes)
    if (std::find(known.begin(), known.end(), c) == known.end())
      throw silodem::CaseError("--codes", "unknown code \"" + c + "\"");
  std::vector<PreparedCompare> cases;
  std::vector<std::string> names;
  for (const auto& f : case_files) {
    cases.push_back(prepare(f, known));  // all input checked first
    names.push_back(cases.back().name);
  }
  require_distinct_case_names(case_files, names);
  std::map<std::string, std::string> cannot_run_parallel;  // by code
  for (const auto& be : backends)
    if (std::string why = be->set_parallel(opt.parallel); !why.empty()) cannot_run_parallel[be->code()] = why;
  if (opt.before_first_run) opt.before_first_run();

  VerifyOutcome out;
  for (const auto& pc : cases) {
    if (!pc.has_compare) {
      out.rows.push_back(skip_row(pc.name, "base", "all", "the case has no \"compare\" section (verify only)"));
      continue;
    }
    // Approach (b) of the silo issue: one filled state, exported by silodem, for every code and
    // every variant — differences after it come from integration and contact law, not from the packing.
    const auto make_state = [&](silodem::CaseConfig lead, const fs::path& src) {
      if (opt.progress)
        std::fprintf(stderr, "[compare] %s: silodem (the case as written, seed %llu) to t = %g s for the shared state\n",
                     pc.name.c_str(), (unsigned long long)lead.seed, pc.from_state_at);
      // A continuation keeps the time step, so the lead runs at the compared runs' step (a clamped
      // law, say, has a shorter contact time and so a shorter dt_per_contact_time step).
      lead.dt = pc.configs.front().dt;
      lead.duration = pc.from_state_at;
      lead.dump_interval_steps = 0;
      // Exactly to that time: the stop tests could end it earlier and leave every code a longer run.
      lead.equilibrium.enabled = false;
      silodem::run_case(lead, {src, false, false});
      return silodem::read_state(src / "state.json");
    };
    std::optional<silodem::StateSnapshot> shared;
    std::vector<silodem::StateSnapshot> seed_states;
    if (pc.from_state_at > 0.0) {
      try {
        shared = make_state(*pc.lead, opt.out_root / pc.name / "shared_state");
        for (std::size_t k = 0; k < pc.seeds.size(); ++k)
          seed_states.push_back(
              make_state(pc.seed_leads[k], opt.out_root / pc.name / ("shared_state_seed" + std::to_string(pc.seeds[k]))));
      } catch (const std::exception& e) {
        out.rows.push_back(
            failed_run_row(pc.name, "all", "all", std::string("the shared state could not be made: ") + e.what()));
        continue;
      }
    }
    for (std::size_t i = 0; i < pc.variants.size(); ++i) {
      const auto& var = pc.variants[i];
      const std::string dir_label = variant_dir_name(var);
      silodem::CaseConfig cfg = pc.configs[i];
      if (shared) {
        try {
          cfg = silodem::continuation(cfg, *shared);
        } catch (const std::exception& e) {
          out.rows.push_back(
              failed_run_row(pc.name, var.label, "all", std::string("cannot continue from the shared state: ") + e.what()));
          continue;
        }
      }
      std::map<std::string, std::vector<CheckRow>> by_code;
      for (const auto& be : backends) {
        const std::string code = be->code();
        if (std::find(pc.codes.begin(), pc.codes.end(), code) == pc.codes.end()) continue;
        if (const auto it = pc.left_out.find(code); it != pc.left_out.end()) {
          out.rows.push_back(skip_row(pc.name, var.label, code, "left out by the case: " + it->second));
          continue;
        }
        if (!opt.codes.empty() && std::find(opt.codes.begin(), opt.codes.end(), code) == opt.codes.end()) {
          // Left out on request: a skip row, so a report of fewer codes never reads as complete.
          out.rows.push_back(skip_row(pc.name, var.label, code, "skipped: not requested (--codes)"));
          continue;
        }
        if (const std::string why = be->missing(); !why.empty()) {
          out.rows.push_back(skip_row(pc.name, var.label, code, "skipped: " + why));
          continue;
        }
        if (const auto it = cannot_run_parallel.find(code); it != cannot_run_parallel.end()) {
          out.rows.push_back(skip_row(pc.name, var.label, code, "skipped: not on " + std::to_string(opt.parallel.ranks) +
                                                                   " ranks: " + it->second));
          continue;
        }
        if (const std::string why = be->not_representable(cfg); !why.empty()) {
          out.rows.push_back(skip_row(pc.name, var.label, code, "not representable: " + why));
          continue;
        }
        if (opt.progress) std::fprintf(stderr, "[compare] %s %s: %s\n", pc.name.c_str(), var.label.c_str(), code.c_str());
        const fs::path dir = opt.out_root / pc.name / dir_label / code;
        const BackendResult br = be->run(cfg, dir, pc.time_limit);
        if (br.status != BackendResult::Status::Ran) {
          // A crash or time-out is an error, not a skip.
          out.rows.push_back(failed_run_row(pc.name, var.label, code, code + " failed: " + br.reason));
          continue;
        }
        const ResultSet rs = read_result(dir);
        const double secs = rs.summary.at("run").value("wall_seconds", 0.0);
        out.run_seconds.emplace_back(pc.name + " " + var.label + " " + code, secs);
        RunContext ctx{cfg, rs, var.label, code};
        for (const auto& check : pc.checks) {
          auto rows = run_check(check, ctx);
          by_code[code].insert(by_code[code].end(), rows.begin(), rows.end());
        }
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
      if (!pc.seeds.empty()) scatter = seed_scatter(pc, i, dir_label, seed_states, by_code["silodem"], opt, out);
      out.rows.insert(out.rows.end(), scatter.begin(), scatter.end());
      std::vector<CheckRow> between_rows;
      std::map<std::string, const CheckRow*> ours;
      for (const auto& r : by_code["silodem"]) ours[r.quantity + "|" + r.subject] = &r;
      for (const auto& [code, rows] : by_code) {
        if (code == "silodem") continue;
        for (const auto& bq : pc.between) {
          if (!bq.codes.empty() && std::find(bq.codes.begin(), bq.codes.end(), code) == bq.codes.end()) continue;
          if (!bq.variants.empty() && std::find(bq.variants.begin(), bq.variants.end(), var.label) == bq.variants.end()) continue;
          std::map<std::string, double> largest;  // per profile, of the reference code's values
          for (const auto& r : rows)
            if (r.quantity == bq.quantity)
              largest[profile_of(r.subject)] = std::max(largest[profile_of(r.subject)], std::abs(r.measured));
          for (const auto& r : rows) {
            if (r.quantity != bq.quantity) continue;
            const auto it = ours.find(r.quantity + "|" + r.subject);
            if (it == ours.end()) continue;
            CheckRow x;
            x.case_name = pc.name;
            x.variant = var.label;
            x.code = "silodem vs " + code;
            x.quantity = r.quantity;
            x.subject = r.subject;
            x.expected = r.measured;           // the reference code's value
            x.measured = it->second->measured;  // silodem's
            // Relative to the reference code's value (or its profile's largest); absolute where that is zero.
            const double scale = bq.relative_to_largest ? largest[profile_of(r.subject)] : x.expected;
            x.error = scale != 0.0 && !bq.absolute ? (x.measured - x.expected) / scale : x.measured - x.expected;
            x.kind = RowKind::Match;
            x.tolerance = bq.tolerance;
            x.tolerance_source = bq.source;
            // A quantity without meaning for these grains is not judged between codes either.
            if (is_frictionless_report(r)) to_report(x, r.reason);
            else if (!bq.report.empty()) to_report(x, bq.report);
            else judge(x);
            if (bq.relative_to_largest) x.note = "difference / largest value of the profile";
            if (bq.absolute) x.note = "plain difference";
            between_rows.push_back(x);
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
