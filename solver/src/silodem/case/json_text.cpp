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

}  // namespace

json parse_case_text(const std::string& text, const std::string& source) {
  std::vector<Level> open;
  const auto element_done = [&open] {
    if (!open.empty() && !open.back().object) ++open.back().index;
  };
  const json::parser_callback_t track = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        open.push_back({event == json::parse_event_t::object_start, open.empty() ? "$" : open.back().member_path(),
                        {}, {}, 0});
        break;
      case json::parse_event_t::key:
        open.back().key = parsed.get<std::string>();
        if (!open.back().keys.insert(open.back().key).second)
          throw CaseError(open.back().member_path(), "duplicate key: \"" + open.back().key +
                                                         "\" is already given in this object (JSON keeps only one)");
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        open.pop_back();
        element_done();
        break;
      case json::parse_event_t::value:
        element_done();
        break;
    }
    return true;
  };
  try {
    return json::parse(text, track);
  } catch (const json::parse_error& e) {
    throw CaseError(source, std::string("malformed JSON: ") + e.what());
  } catch (const json::out_of_range& e) {
    // A literal beyond the double range (1e400): the open levels still say whose value it was.
    const std::string what = e.what();
    throw CaseError(open.empty() ? source : open.back().member_path(),
                    "out of range: " + what.substr(what.find(']') + 2) + " (beyond the double range)");
  }
}

}  // namespace silodem
