#pragma once
// The one JSON reader for every file Kerf reads (projects, logs, presets, block.json), in the CLI and
// the editor alike (issue 21): the file is opened safely (io/input_file.hpp: regular files only, at most
// kMaxJsonFileBytes), lists and objects nested deeper than kMaxJsonDepth are refused while parsing (a
// 100,000-deep list must not overflow the stack of whatever walks or prints it later), a key repeated in
// one object is refused naming it (nlohmann keeps the last silently), and no message quotes more than
// about 80 characters of the file.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace kerf {

inline constexpr int kMaxJsonDepth = 64;  // Kerf's own files nest 6 deep at most

// Parses `text`; throws InputError "<source> is not valid JSON (byte N): why" and the like.
nlohmann::json parseJsonText(std::string_view text, const std::string& source);

// Reads and parses a file; `kind` names it in messages ("project", "log file").
nlohmann::json readJsonFile(const std::filesystem::path& path, const std::string& kind);

// A value for an error message: strings and numbers quoted and cut to about 80 characters, lists and
// objects described by their size (never dumped whole).
std::string describeJson(const nlohmann::json& value);

}  // namespace kerf
