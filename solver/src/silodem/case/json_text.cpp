#include "silodem/case/json_text.hpp"

#include <cmath>
#include <set>
#include <vector>

#include "silodem/case/case_error.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/case/memory_estimate.hpp"
#include "silodem/case/text_position.hpp"
#include "silodem/core/available_memory.hpp"

namespace silodem {

using nlohmann::json;

namespace {

/// One open object or array while parsing. Only its own step of the JSON path is kept (the key or
/// index of the member being parsed), so the levels hold memory linear in the input; the full path
/// is put together only when an error names it.
struct Level {
  bool object = false;
  std::set<std::string> keys;  // the object's keys so far (duplicates are refused)
  std::string key;             // the member being parsed (objects)
  std::size_t index = 0;       // the element being parsed (arrays)
  double key_bytes = 0.0;      // what `keys` holds, counted in the budget while the object is open
};

/// The offset of the first '[' or '{' that opens level depth + 1. Called only once the parser has
/// stopped there, so the text before it is valid JSON and a scan for brackets outside strings
/// finds the same place.
std::size_t opening_beyond(const std::string& text, std::size_t depth) {
  std::size_t open = 0;
  bool in_string = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++open > depth) return i;
    } else if (c == ']' || c == '}') {
      --open;
    }
  }
  return text.size();
}

/// SAX events: tracks the path and refuses duplicate keys and nesting beyond limits::kJsonDepth,
/// then hands each event to the library's own DOM builder. Not json::parse with a callback: in
/// nlohmann-json 3.11 (Debian 12) the callback parser scans the whole parent container at the end
/// of every object, so an array of N balls took O(N²) — minutes for a case of 10^6 balls
/// (nlohmann/json pull request 5457).
class TrackingBuilder final : public nlohmann::json_sax<json> {
 public:
  /// `budget`: the bytes the document may take as it is built (see dom_bytes_).
  TrackingBuilder(json& result, double budget) : dom_(result, true), budget_(budget) {}
  bool too_deep() const { return too_deep_; }
  bool too_big() const { return dom_bytes_ > budget_; }
  double dom_bytes() const { return dom_bytes_; }

  /// The JSON path of the member being parsed ("$" outside every container).
  std::string member_path() const {
    std::string path = "$";
    for (const Level& l : open_) path += l.object ? "." + l.key : "[" + std::to_string(l.index) + "]";
    return path;
  }

  bool null() override { return value_done(0) && dom_.null(); }
  bool boolean(bool v) override { return value_done(0) && dom_.boolean(v); }
  bool number_integer(number_integer_t v) override { return value_done(0) && dom_.number_integer(v); }
  bool number_unsigned(number_unsigned_t v) override { return value_done(0) && dom_.number_unsigned(v); }
  bool number_float(number_float_t v, const string_t& s) override { return value_done(0) && dom_.number_float(v, s); }
  bool string(string_t& v) override { return value_done(kStringBytes + text_bytes(v)) && dom_.string(v); }
  bool binary(binary_t& v) override { return value_done(kStringBytes + double(v.size())) && dom_.binary(v); }
  bool start_object(std::size_t n) override { return open_level(true) && dom_.start_object(n); }
  bool start_array(std::size_t n) override { return open_level(false) && dom_.start_array(n); }
  bool end_object() override { return close_level() && dom_.end_object(); }
  bool end_array() override { return close_level() && dom_.end_array(); }
  bool key(string_t& k) override {
    Level& l = open_.back();
    l.key = k;
    const double bytes = kMemberBytes + kKeySetBytes + 2.0 * text_bytes(k);  // the document's and the set's
    dom_bytes_ += bytes;
    l.key_bytes += kKeySetBytes + text_bytes(k);
    if (too_big()) return false;
    if (!l.keys.insert(k).second)
      throw CaseError(member_path(), "duplicate key: \"" + k + "\" is already given in this object (JSON keeps only one)");
    return dom_.key(k);
  }
  bool parse_error(std::size_t pos, const std::string& token, const nlohmann::detail::exception& ex) override {
    return dom_.parse_error(pos, token, ex);  // throws (as json::exception)
  }

 private:
  // What the DOM takes (nlohmann-json on libstdc++, malloc's chunks): a member of an object (map
  // node with its key), an element of an array (16 bytes, room for twice as it grows), a container,
  // a string; see json_heap_bytes (memory_estimate.hpp), which measures a finished document alike.
  static constexpr double kMemberBytes = 96, kElementBytes = 32, kContainerBytes = 64, kStringBytes = 48;
  static constexpr double kKeySetBytes = 80;  // a node of a Level's key set
  static double text_bytes(const std::string& s) { return s.size() > 15 ? double(s.size() + 24) : 0.0; }

  /// A value is complete; `bytes` it holds besides its slot. False stops the parser (over budget).
  bool value_done(double bytes) {
    dom_bytes_ += bytes;
    if (!open_.empty() && !open_.back().object) ++open_.back().index, dom_bytes_ += kElementBytes;
    return !too_big();
  }
  bool open_level(bool object) {
    if (open_.size() >= std::size_t(limits::kJsonDepth)) {
      too_deep_ = true;  // stops the parser here, before the DOM grows deeper
      return false;
    }
    dom_bytes_ += kContainerBytes;
    if (too_big()) return false;
    open_.push_back({object, {}, {}, 0, 0.0});
    return true;
  }
  bool close_level() {
    dom_bytes_ -= open_.back().key_bytes;
    open_.pop_back();
    return value_done(0);
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::vector<Level> open_;
  bool too_deep_ = false;
  double budget_, dom_bytes_ = 0.0;
};

}  // namespace

json parse_case_text(const std::string& text, const std::string& source) {
  json result;
  // Stopped at three quarters of what the process may still take: the rest is for what comes
  // next, and a document half built must still be taken apart (which allocates, too).
  const auto room = available_memory();
  TrackingBuilder builder(result, room ? 0.75 * room->bytes : INFINITY);
  bool complete = false;
  try {
    complete = json::sax_parse(text, &builder);
  } catch (const json::exception& e) {
    // The DOM builder rethrows as the base class; the id says which: 1xx syntax, 406 a literal
    // beyond the double range (1e400), whose path the open levels still give.
    const std::string what = e.what();
    if (e.id / 100 != 4) throw CaseError(source, "malformed JSON: " + what);
    throw CaseError(builder.member_path(), "out of range: " + what.substr(what.find(']') + 2) + " (beyond the double range)");
  }
  if (builder.too_deep()) {
    const TextPosition at = position_in(text, opening_beyond(text, std::size_t(limits::kJsonDepth)));
    throw CaseError(source, at.describe() + ": arrays and objects nested deeper than " +
                                std::to_string(limits::kJsonDepth) + " levels (a case file needs fewer than 10)");
  }
  if (builder.too_big())
    throw CaseError(source, "reading the case file into memory takes more than " + format_bytes(builder.dom_bytes()) +
                                ", more than three quarters of the " + format_bytes(room->bytes) +
                                " this process can still take (" + room->source + ")");
  if (!complete) throw CaseError(source, "malformed JSON: the parser stopped early");
  return result;
}

}  // namespace silodem
