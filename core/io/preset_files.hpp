#pragma once
// Species preset files (params/presets.hpp describes the format): one JSON file per species, as in
// resources/presets/. The editor and the CLI use the presets compiled in (params/builtin_presets.hpp).
#include <filesystem>
#include <vector>

#include "params/presets.hpp"

namespace kerf {

// Reads one preset file; errors name the file. The id must equal the file stem.
Preset loadPreset(const std::filesystem::path& file);
// Every *.json in `folder`, sorted by name (then id). Throws InputError for a missing folder, a
// malformed file (naming it) or two presets with the same id.
std::vector<Preset> loadPresets(const std::filesystem::path& folder);

}  // namespace kerf
