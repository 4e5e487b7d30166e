#include "util/json_text.hpp"

#include <set>
#include <vector>

#include "util/error.hpp"
#include "util/parse_number.hpp"

namespace kerf {
using nlohmann::json;
namespace {

// nlohmann's message without its "[json.exception.parse_error.101] " prefix, and with the token it
// quotes ("last read: '...'") cut: a 50 MB string must not be echoed whole.
std::string jsonProblem(const json::exception& e) {
  std::string what = e.what();
  const auto end = what.find("] ");
  if (end != std::string::npos) what = what.substr(end + 2);
  const std::string marker = "last read: '";
  const auto token = what.find(marker);
  if (token != std::string::npos) {
    const std::size_t start = token + marker.size();
    const std::size_t close = what.find('\'', start);
    const std::string quoted =
        what.substr(start, close == std::string::npos ? std::string::npos : close - start);
    const std::string rest = close == std::string::npos ? "" : what.substr(close + 1);
    what = what.substr(0, token) + "last read: " + quoteForMessage(quoted) + rest;
  }
  if (what.size() > 300) what = what.substr(0, 300) + "...";
  return what;
}

}  // namespace

json parseJsonText(std::string_view text, const std::string& source) {
  // Keys seen in each open object, innermost last; the parser calls back before it descends.
  std::vector<std::set<std::string>> keys;
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (depth >= kMaxJsonDepth)
          throw InputError(source + " is not valid for Kerf: lists and objects nested deeper than " +
                           std::to_string(kMaxJsonDepth) + " levels");
        if (event == json::parse_event_t::object_start) keys.emplace_back();
        break;
      case json::parse_event_t::object_end:
        keys.pop_back();
        break;
      case json::parse_event_t::key:
        if (!keys.back().insert(parsed.get<std::string>()).second)
          throw InputError(source + ": the key " + quoteForMessage(parsed.get<std::string>()) +
                           " appears twice in one object");
        break;
      default:
        break;
    }
    return true;
  };
  try {
    return json::parse(text.begin(), text.end(), check);
  } catch (const json::parse_error& e) {
    throw InputError(source + " is not valid JSON (byte " + std::to_string(e.byte) + "): " + jsonProblem(e));
  } catch (const json::exception& e) {  // e.g. a number too large for a double (1e999)
    throw InputError(source + " is not valid JSON: " + jsonProblem(e));
  }
}

std::string describeJson(const json& value) {
  if (value.is_array()) return "a list of " + std::to_string(value.size()) + " entries";
  if (value.is_object()) return "an object of " + std::to_string(value.size()) + " keys";
  if (value.is_string()) return "the text " + quoteForMessage(value.get_ref<const std::string&>());
  if (value.is_null()) return "null";
  return value.dump();  // a number or true/false: short
}

float readJsonNumber(const json& value, const std::string& what) {
  if (!value.is_number()) throw InputError(what + " must be a number, got " + describeJson(value));
  return checkedNumber<float>(value.get<double>(), what);
}

glm::vec3 readJsonVec3(const json& value, const std::string& what) {
  if (!value.is_array() || value.size() != 3)
    throw InputError(what + " must be a list of 3 numbers, got " + describeJson(value));
  return {readJsonNumber(value[0], what), readJsonNumber(value[1], what), readJsonNumber(value[2], what)};
}

}  // namespace kerf
