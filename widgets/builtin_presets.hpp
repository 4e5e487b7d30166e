#pragma once
// The species presets shipped inside the editor (resources/presets/*.json, compiled into the binary as
// the Qt resource :/presets/). See core/params/presets.hpp for the format and what applying one keeps.
#include <QString>
#include <vector>

#include "params/presets.hpp"

namespace kerf {

// Every built-in preset, sorted by name. Read and checked once, on first use; a preset that fails to
// parse is left out with a warning (the files are checked by tests/core/test_presets.cpp).
const std::vector<Preset>& builtInPresets();

// The built-in preset with this id, or nullptr.
const Preset* builtInPreset(const QString& id);

}  // namespace kerf
