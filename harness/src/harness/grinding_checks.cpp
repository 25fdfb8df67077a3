#include "harness/grinding_checks.hpp"

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "harness/result_files.hpp"

namespace harness {

using nlohmann::json;

namespace {

/// The material's grains by radius, changed break by break.
class SizePopulation {
 public:
  void add(double r, long count = 1) { radii_[r] += count; }
  /// Replaces one grain of radius r (as the log prints it, 12 digits) by n of r n^(-1/3).
  void split(double r, int n, double t) {
    auto it = radii_.lower_bound(r * (1.0 - 1e-9));
    if (it == radii_.end() || it->first > r * (1.0 + 1e-9))
      throw std::runtime_error("breakage.csv: a break at t = " + std::to_string(t) + " of a grain of radius " +
                               std::to_string(r) + " m, which the material has none of at that time");
    const double exact = it->first;
    if (--it->second == 0) radii_.erase(it);
    add(exact / std::cbrt(double(n)), n);
  }
  long count() const {
    long n = 0;
    for (const auto& [r, k] : radii_) n += k;
    return n;
  }
  /// The mass fraction in grains of radius below x (one density: volumes).
  double passing(double x) const {
    double below = 0.0, all = 0.0;
    for (const auto& [r, k] : radii_) {
      const double v = double(k) * r * r * r;
      all += v;
      if (r < x) below += v;
    }
    return all > 0.0 ? below / all : 0.0;
  }

 private:
  std::map<double, long> radii_;
};

std::string seconds(double t) {
  std::ostringstream s;
  s << t << " s";
  return s.str();
}

}  // namespace

std::vector<CheckRow> size_distribution(const json& spec, const RunContext& ctx) {
  const std::string material = spec.at("material"), charge_probe = spec.at("charge_probe");
  const double every = spec.at("every").get<double>();
  const std::vector<double> sieves = spec.at("sieves").get<std::vector<double>>();
  SizePopulation grains;
  long others = 0;  // the charge's grains of other materials
  for (const auto& b : ctx.cfg.balls)
    if (!b.fixed) (b.material == material ? grains.add(b.radius) : void(++others));
  const CsvTable log = read_csv(ctx.result.dir / "breakage.csv");
  const double end = ctx.result.summary.at("run").at("time").get<double>();
  std::vector<CheckRow> out;
  const auto sample = [&](double t) {
    const std::string at = material + " at " + seconds(t);
    out.push_back(report_row(ctx, "grains", at, double(grains.count()), "a grinding result: the model's toughness is random"));
    for (const double x : sieves) {
      std::ostringstream subject;
      subject << at << ", r < " << x << " m";
      out.push_back(report_row(ctx, "mass_fraction_passing", subject.str(), grains.passing(x),
                               "a grinding result: the model's toughness is random"));
    }
  };
  std::size_t row = 0;
  for (double t = 0.0; t < end + 1e-9 * every; t += every) {
    for (; row < log.size() && log.number(row, "t") <= t; ++row)
      grains.split(log.number(row, "radius"), int(log.number(row, "fragments")), log.number(row, "t"));
    sample(t);
  }
  for (; row < log.size(); ++row)
    grains.split(log.number(row, "radius"), int(log.number(row, "fragments")), log.number(row, "t"));
  if (std::fmod(end, every) > 1e-9 * every) sample(end);
  const double counted = ctx.result.probe_digest(charge_probe).at("final").at("balls").get<double>();
  out.push_back(match_row(ctx, "grains_from_break_log", charge_probe, counted, double(grains.count() + others), 1e-12,
                          "exact: each break replaces one grain by n (breakage.csv against the charge probe's count)"));
  return out;
}

void validate_size_distribution(const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  if (!cfg.breakage) r.fail("type", "the case has no breakage");
  const std::string material = r.string("material");
  bool breakable = false;
  for (const auto& m : cfg.breakage->materials) breakable |= m == material;
  if (!breakable) r.fail("material", "\"" + material + "\" is not one of breakage.materials");
  if (cfg.drops) r.fail("type", "the size distribution starts from the case's listed grains; a case with drops has others");
  r.number_in("every", 1e-6, 1e6, "s");
  const json& sieves = r.array("sieves");
  if (sieves.empty()) r.fail("sieves", "needs at least one size (m)");
  for (std::size_t k = 0; k < sieves.size(); ++k)
    silodem::json_number_in(sieves[k], r.child_path("sieves") + "[" + std::to_string(k) + "]", 1e-9, 1e3, "m");
  const std::string probe = r.string("charge_probe");
  for (const auto& p : cfg.probes)
    if (p.name == probe && p.type == "charge") return;
  r.fail("charge_probe", "no charge probe named \"" + probe + "\"");
}

}  // namespace harness
