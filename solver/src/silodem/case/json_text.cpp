#include "silodem/case/json_text.hpp"

#include <set>
#include <vector>

#include "silodem/case/case_error.hpp"

namespace silodem {

using nlohmann::json;

namespace {

/// One open object or array while parsing: enough to rebuild the JSON path of its next member.
struct Level {
  bool object = false;
  std::string path;
  std::set<std::string> keys;
  std::string key;        // the member being parsed (objects)
  std::size_t index = 0;  // the element being parsed (arrays)
  std::string member_path() const {
    return object ? path + "." + key : path + "[" + std::to_string(index) + "]";
  }
};

/// SAX events: tracks the path and refuses duplicate keys, then hands each event to the library's
/// own DOM builder. Not json::parse with a callback: in nlohmann-json 3.11 (Debian 12) the callback
/// parser scans the whole parent container at the end of every object, so an array of N balls
/// took O(N²) — minutes for a case of 10^6 balls (nlohmann/json pull request 5457).
class TrackingBuilder final : public nlohmann::json_sax<json> {
 public:
  explicit TrackingBuilder(json& result) : dom_(result, true) {}
  const std::vector<Level>& open() const { return open_; }

  bool null() override { return value_done() && dom_.null(); }
  bool boolean(bool v) override { return value_done() && dom_.boolean(v); }
  bool number_integer(number_integer_t v) override { return value_done() && dom_.number_integer(v); }
  bool number_unsigned(number_unsigned_t v) override { return value_done() && dom_.number_unsigned(v); }
  bool number_float(number_float_t v, const string_t& s) override { return value_done() && dom_.number_float(v, s); }
  bool string(string_t& v) override { return value_done() && dom_.string(v); }
  bool binary(binary_t& v) override { return value_done() && dom_.binary(v); }
  bool start_object(std::size_t n) override { return open_level(true) && dom_.start_object(n); }
  bool start_array(std::size_t n) override { return open_level(false) && dom_.start_array(n); }
  bool end_object() override { return close_level() && dom_.end_object(); }
  bool end_array() override { return close_level() && dom_.end_array(); }
  bool key(string_t& k) override {
    Level& l = open_.back();
    l.key = k;
    if (!l.keys.insert(k).second)
      throw CaseError(l.member_path(), "duplicate key: \"" + k + "\" is already given in this object (JSON keeps only one)");
    return dom_.key(k);
  }
  bool parse_error(std::size_t pos, const std::string& token, const nlohmann::detail::exception& ex) override {
    return dom_.parse_error(pos, token, ex);  // throws (as json::exception)
  }

 private:
  bool value_done() {
    if (!open_.empty() && !open_.back().object) ++open_.back().index;
    return true;
  }
  bool open_level(bool object) {
    open_.push_back({object, open_.empty() ? "$" : open_.back().member_path(), {}, {}, 0});
    return true;
  }
  bool close_level() {
    open_.pop_back();
    return value_done();
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::vector<Level> open_;
};

}  // namespace

json parse_case_text(const std::string& text, const std::string& source) {
  json result;
  TrackingBuilder builder(result);
  try {
    json::sax_parse(text, &builder);
  } catch (const json::exception& e) {
    // The DOM builder rethrows as the base class; the id says which: 1xx syntax, 406 a literal
    // beyond the double range (1e400), whose path the open levels still give.
    const std::string what = e.what();
    if (e.id / 100 != 4) throw CaseError(source, "malformed JSON: " + what);
    throw CaseError(builder.open().empty() ? source : builder.open().back().member_path(),
                    "out of range: " + what.substr(what.find(']') + 2) + " (beyond the double range)");
  }
  return result;
}

}  // namespace silodem
