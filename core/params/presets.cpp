#include "params/presets.hpp"

#include <algorithm>

#include "params/parameter_json.hpp"
#include "util/error.hpp"
#include "util/parse_number.hpp"

namespace kerf {
using nlohmann::json;

namespace {

// The schema's ParamScope::Block parameters: they describe this block, not the species.
const std::vector<std::string_view>& keptIds() {
  static const std::vector<std::string_view> ids = [] {
    std::vector<std::string_view> out;
    for (const ParamSpec& spec : parameterSchema())
      if (spec.scope == ParamScope::Block) out.push_back(spec.id);
    return out;
  }();
  return ids;
}

bool isKept(std::string_view id) {
  const ParamSpec* spec = findParameter(id);
  return spec && spec->scope == ParamScope::Block;
}

std::string readString(const json& in, const char* key, bool required) {
  if (!in.contains(key)) {
    if (required) throw InputError(std::string("the preset has no \"") + key + "\"");
    return {};
  }
  if (!in[key].is_string()) throw InputError(std::string("\"") + key + "\" must be a string");
  return in[key].get<std::string>();
}

bool validId(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

}  // namespace

std::span<const std::string_view> presetKeptParameterIds() {
  return keptIds();
}

WoodParameters Preset::parametersOnDefaults() const {
  return parametersFromJson(parameters);
}

WoodParameters Preset::applyTo(const WoodParameters& base) const {
  WoodParameters out = parametersOnDefaults();
  const auto schema = parameterSchema();
  for (std::size_t i = 0; i < schema.size(); ++i) {
    if (schema[i].scope != ParamScope::Block) continue;
    const auto from = base.components(i);
    std::copy(from.begin(), from.end(), out.components(i).begin());
  }
  validate(out);
  return out;
}

Preset presetFromJson(const json& in) {
  if (!in.is_object() || !in.contains("format") || in["format"] != kPresetFormatName) {
    throw InputError(std::string("not a Kerf preset (missing \"format\": \"") + kPresetFormatName + "\")");
  }
  if (!in.contains("version") || !in["version"].is_number_integer()) {
    throw InputError("the preset has no format version");
  }
  const int version = checkedNumber<int>(in["version"].get<double>(), "version");
  if (version > kPresetFormatVersion) {
    throw InputError("the preset was written by a newer Kerf (format version " + std::to_string(version) +
                     "); this Kerf reads versions up to " + std::to_string(kPresetFormatVersion));
  }
  if (version < 1) throw InputError("unknown preset format version " + std::to_string(version));

  Preset preset;
  preset.id = readString(in, "id", true);
  if (!validId(preset.id)) {
    throw InputError("preset id \"" + preset.id + "\" must be lower-case letters, digits, '_' or '-'");
  }
  preset.name = readString(in, "name", true);
  if (preset.name.empty()) throw InputError("preset \"" + preset.id + "\" has an empty name");
  preset.latin = readString(in, "latin", false);
  preset.mokumeCode = readString(in, "mokume_code", false);
  preset.description = readString(in, "description", false);

  if (!in.contains("parameters")) throw InputError("preset \"" + preset.id + "\" has no \"parameters\"");
  preset.parameters = in["parameters"];
  if (!preset.parameters.is_object()) {
    throw InputError("\"parameters\" of preset \"" + preset.id + "\" must be an object of id: value pairs");
  }
  for (const auto& item : preset.parameters.items()) {
    if (isKept(item.key())) {
      throw InputError("preset \"" + preset.id + "\" sets \"" + item.key() +
                       "\", which describes the block, not the species (presets keep it)");
    }
  }
  try {
    parametersFromJson(preset.parameters);  // ids known, values finite and inside the hard ranges
  } catch (const InputError& e) {
    throw InputError("preset \"" + preset.id + "\": " + e.what());
  }
  return preset;
}

json presetToJson(const Preset& preset) {
  json out = {{"format", kPresetFormatName},
              {"version", kPresetFormatVersion},
              {"id", preset.id},
              {"name", preset.name}};
  if (!preset.latin.empty()) out["latin"] = preset.latin;
  if (!preset.mokumeCode.empty()) out["mokume_code"] = preset.mokumeCode;
  if (!preset.description.empty()) out["description"] = preset.description;
  out["parameters"] = preset.parameters;
  return out;
}

const Preset* findPreset(std::span<const Preset> presets, std::string_view id) {
  for (const Preset& preset : presets) {
    if (preset.id == id) return &preset;
  }
  return nullptr;
}

}  // namespace kerf
