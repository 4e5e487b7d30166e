#pragma once
// Parsing JSON text, and reading its values strictly, for every JSON Kerf reads (projects, logs,
// presets, block.json; io/json_file.hpp opens the files): lists and objects nested deeper than
// kMaxJsonDepth are refused while parsing (a 100,000-deep list must not overflow the stack of whatever
// walks or prints it later), a key repeated in one object is refused naming it (nlohmann keeps the last
// silently), and no message quotes more than about 80 characters of the text.
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace kerf {

inline constexpr int kMaxJsonDepth = 64;  // Kerf's own files nest 6 deep at most

// Parses `text`; throws InputError "<source> is not valid JSON (byte N): why" and the like.
nlohmann::json parseJsonText(std::string_view text, const std::string& source);

// A value for an error message: strings and numbers quoted and cut to about 80 characters, lists and
// objects described by their size (never dumped whole).
std::string describeJson(const nlohmann::json& value);

// nlohmann stores NaN/inf as null; numbers are read strictly so a null or a string is a clear error.
// InputError naming `what`.
float readJsonNumber(const nlohmann::json& value, const std::string& what);
// A list of 3 numbers, read as readJsonNumber reads each.
glm::vec3 readJsonVec3(const nlohmann::json& value, const std::string& what);

}  // namespace kerf
