#include "harness/compare_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "harness/case_names.hpp"
#include "harness/checks.hpp"
#include "harness/janssen_prediction.hpp"
#include "harness/tolerance_source.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

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

}  // namespace

PreparedCompare prepare_compare(const fs::path& file, const std::vector<std::string>& known_codes) {
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
        x.at_frames = b.choice_or("silodem_sampled", {"every_step", "at_frames"}, "every_step") == "at_frames";
        // A time mean over a chaotic flow: each run, the reference codes' too, is one realisation, and
        // the mean of silodem's is the better estimate of its law's value than any one of them.
        x.seeds_mean = b.choice_or("silodem_value", {"run", "seeds_mean"}, "run") == "seeds_mean";
        if (x.seeds_mean && !c.has("seeds")) b.fail("silodem_value", "\"seeds_mean\" needs compare.seeds");
        if (x.seeds_mean && x.at_frames) b.fail("silodem_value", "\"seeds_mean\" takes every realisation's own probes, not its frames");
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
    const std::vector<std::string> axes = variant_axes(pc.variants);
    for (const auto& var : pc.variants) {
      pc.configs.push_back(load_variant(var, "compare variant"));
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

}  // namespace harness
