#pragma once
// The one JSON file reader for every file Kerf reads (projects, logs, presets, block.json), in the CLI and
// the editor alike (issue 21): the file is opened safely (io/input_file.hpp: regular files only, at most
// kMaxJsonFileBytes), then parsed as util/json_text.hpp parses any JSON text.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "util/json_text.hpp"

namespace kerf {

// Reads and parses a file; `kind` names it in messages ("project", "log file").
nlohmann::json readJsonFile(const std::filesystem::path& path, const std::string& kind);

}  // namespace kerf
