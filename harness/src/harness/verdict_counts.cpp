#include "harness/verdict_counts.hpp"

#include <set>

namespace harness {

namespace {
std::string class_of(const CheckRow& r) { return r.skipped ? "skip" : r.judged() ? "judged" : "report"; }
}  // namespace

std::vector<QuantityLine> quantity_lines(const std::vector<CheckRow>& rows) {
  std::vector<QuantityLine> lines;
  std::map<std::string, std::size_t> index;
  for (const auto& r : rows) {
    const std::string cls = class_of(r);
    const std::string key = r.case_name + "|" + r.variant + "|" + r.code + "|" + r.quantity + "|" + cls;
    auto it = index.find(key);
    if (it == index.end()) {
      it = index.emplace(key, lines.size()).first;
      lines.push_back({r.case_name, r.variant, r.code, r.quantity, cls, {}, 0});
    }
    QuantityLine& l = lines[it->second];
    l.rows.push_back(&r);
    l.passed += r.judged() && r.pass;
  }
  return lines;
}

Headline headline(const std::vector<CheckRow>& rows) {
  Headline h;
  std::map<std::string, std::size_t> case_index;
  std::map<std::string, std::set<std::string>> variants;
  std::set<std::string> all_variants;
  for (const auto& l : quantity_lines(rows)) {
    auto it = case_index.find(l.case_name);
    if (it == case_index.end()) {
      it = case_index.emplace(l.case_name, h.cases.size()).first;
      h.cases.push_back({l.case_name, {}});
    }
    for (VerdictCounts* c : {&h.cases[it->second].second, &h.total}) {
      if (l.cls == "judged") {
        ++c->judged;
        c->judged_passed += l.pass();
        c->rows += l.rows.size();
        c->rows_passed += l.passed;
      } else if (l.cls == "report") {
        ++c->reported;
        c->report_rows += l.rows.size();
      } else {
        c->skipped_rows += l.rows.size();
      }
    }
    variants[l.case_name].insert(l.variant);
    all_variants.insert(l.case_name + "|" + l.variant);
  }
  for (auto& [name, c] : h.cases) c.variants = variants[name].size();
  h.total.variants = all_variants.size();
  return h;
}

std::string headline_sentence(const VerdictCounts& c) {
  std::string s = std::to_string(c.judged_passed) + " of " + std::to_string(c.judged) + " judged quantities passed (" +
                  std::to_string(c.rows_passed) + " of " + std::to_string(c.rows) + " judged sub-rows); " +
                  std::to_string(c.reported) + " quantities (" + std::to_string(c.report_rows) +
                  " rows) reported, not judged; " + std::to_string(c.skipped_rows) + " rows skipped";
  if (c.judged == 0) s += "; nothing was judged";
  return s;
}

}  // namespace harness
