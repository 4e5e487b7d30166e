#include "params/builtin_presets.hpp"

#include <algorithm>
#include <cctype>

#include "util/error.hpp"

namespace kerf {
namespace {

std::vector<Preset> readPresets() {
  std::vector<Preset> presets;
  for (const PresetText& text : builtInPresetTexts()) {
    try {
      Preset preset = presetFromJson(nlohmann::json::parse(text.json));
      if (preset.id + ".json" != text.fileName)
        throw InputError("its id \"" + preset.id + "\" does not match the file name");
      presets.push_back(std::move(preset));
    } catch (const std::exception& e) {
      throw InputError(std::string("built-in preset ") + text.fileName + ": " + e.what());
    }
  }
  std::sort(presets.begin(), presets.end(), [](const Preset& a, const Preset& b) {
    return a.name != b.name ? a.name < b.name : a.id < b.id;
  });
  return presets;
}

}  // namespace

const std::vector<Preset>& builtInPresets() {
  static const std::vector<Preset> presets = readPresets();
  return presets;
}

const Preset* builtInPreset(std::string_view id) {
  return findPreset(builtInPresets(), id);
}

const Preset* builtInPresetForSampleName(std::string_view sampleName) {
  std::string code;
  for (char c : sampleName) {
    if (!std::isalpha(static_cast<unsigned char>(c))) break;
    code += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  if (code.empty() || code.size() == sampleName.size()) return nullptr;  // a code must precede a number
  if (!std::isdigit(static_cast<unsigned char>(sampleName[code.size()]))) return nullptr;
  for (const Preset& preset : builtInPresets())
    if (preset.mokumeCode == code) return &preset;
  return nullptr;
}

}  // namespace kerf
