#include "harness/seed_scatter.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace harness {

std::string profile_of(const std::string& subject) {
  const auto k = subject.rfind(" band ");
  return k == std::string::npos ? subject : subject.substr(0, k);
}

std::vector<CheckRow> seed_scatter_rows(const std::vector<ScatterQuantity>& quantities, const std::vector<CheckRow>& main_rows,
                                        const std::vector<std::vector<CheckRow>>& seed_rows,
                                        const std::string& seeds_label) {
  std::vector<CheckRow> out;
  for (const auto& q : quantities) {
    std::vector<CheckRow> rows;
    std::map<std::string, double> largest;  // per profile, of the means
    std::set<std::string> seen;  // two checks may give the same quantity and subject (janssen and static_balance)
    for (const auto& m : main_rows) {
      if (m.quantity != q.quantity || !seen.insert(m.subject).second) continue;
      std::vector<double> v{m.measured};
      for (const auto& seed : seed_rows)
        for (const auto& s : seed)
          if (s.quantity == m.quantity && s.subject == m.subject) {
            v.push_back(s.measured);  // one value per realisation
            break;
          }
      double mean = 0.0, var = 0.0;
      for (double x : v) mean += x / double(v.size());
      for (double x : v) var += (x - mean) * (x - mean);
      CheckRow r = m;
      r.code = "silodem seeds";
      r.expected = mean;
      r.measured = v.size() > 1 ? std::sqrt(var / double(v.size() - 1)) : std::nan("");
      r.tolerance = NAN;
      r.tolerance_source.clear();
      char note[160];
      std::snprintf(note, sizeof note, "sample std over %zu realisations (%s); ", v.size(), seeds_label.c_str());
      r.note = note;
      largest[profile_of(r.subject)] = std::max(largest[profile_of(r.subject)], std::abs(mean));
      rows.push_back(r);
    }
    for (auto& r : rows) {
      const double scale = q.scale == DifferenceScale::Absolute          ? 1.0
                           : q.scale == DifferenceScale::LargestOfProfile ? largest[profile_of(r.subject)]
                                                                          : std::abs(r.expected);
      r.error = scale > 0.0 ? r.measured / scale : r.measured;
      r.note += q.scale == DifferenceScale::Absolute          ? "error = std"
                : q.scale == DifferenceScale::LargestOfProfile ? "error = std / largest mean of the profile"
                                                               : "error = std / |mean|";
      to_report(r, "the scatter of silodem's own realisations: the yardstick for between_codes, not a verdict");
      out.push_back(r);
    }
  }
  return out;
}

void annotate_with_scatter(std::vector<CheckRow>& between_rows, const std::vector<CheckRow>& scatter_rows) {
  for (auto& b : between_rows)
    for (const auto& s : scatter_rows)
      if (s.quantity == b.quantity && s.subject == b.subject && s.variant == b.variant && s.case_name == b.case_name) {
        char note[160];
        std::snprintf(note, sizeof note, "%sseed scatter %.3g (same scale): |difference|/scatter = %.3g",
                      b.note.empty() ? "" : "; ", s.error, s.error > 0.0 ? std::abs(b.error) / s.error : std::nan(""));
        b.note += note;
      }
}

}  // namespace harness
