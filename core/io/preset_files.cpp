#include "io/preset_files.hpp"

#include <algorithm>
#include <set>
#include <string>

#include "io/json_file.hpp"
#include "util/error.hpp"

namespace kerf {
namespace fs = std::filesystem;
using nlohmann::json;

Preset loadPreset(const fs::path& file) {
  const json in = readJsonFile(file, "preset");
  Preset preset;
  try {
    preset = presetFromJson(in);
  } catch (const InputError& e) {
    throw InputError("preset " + file.string() + ": " + e.what());
  } catch (const json::exception& e) {
    throw InputError("preset " + file.string() + ": a value has the wrong type (" + e.what() + ")");
  }
  if (preset.id != file.stem().string()) {
    throw InputError("preset " + file.string() + ": its id \"" + preset.id + "\" must match the file name");
  }
  return preset;
}

std::vector<Preset> loadPresets(const fs::path& folder) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw InputError("preset folder " + folder.string() + " does not exist or is not a folder");
  }
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<Preset> presets;
  std::set<std::string> ids;
  for (const auto& file : files) {
    presets.push_back(loadPreset(file));
    if (!ids.insert(presets.back().id).second) {
      throw InputError("preset " + file.string() + ": another preset already has the id \"" +
                       presets.back().id + "\"");
    }
  }
  std::sort(presets.begin(), presets.end(), [](const Preset& a, const Preset& b) {
    return a.name != b.name ? a.name < b.name : a.id < b.id;
  });
  return presets;
}

}  // namespace kerf
