#pragma once
// Species presets: plausible starting points for the procedural wood of one species (ring width,
// earlywood/latewood and heartwood/sapwood colours, pores, rays...), one JSON file per species in
// resources/presets/ (the 17 species of the Mokume dataset, Table 1).
//
// File format:
//   {"format": "kerf-preset", "version": 1, "id": "kuri", "name": "Japanese chestnut (kuri)",
//    "latin": "Castanea crenata", "mokume_code": "CN", "description": "one line in wood terms",
//    "parameters": {"growth.ring_width": 3.0, "color.earlywood": [r, g, b], ...}}
// "parameters" lists only the values that differ from the schema defaults (wood_parameters.def).
//
// Applying a preset: the species' values are set on top of the schema defaults, but everything that
// describes *this block* rather than the species is kept from the current parameters: where the pith
// lies and how it leans (growth.pith_origin, pith_tilt, pith_azimuth), the ring phase and eccentric
// growth (fitted or set for this log), the per-face photo tints, and the random seed: the schema's
// ParamScope::Block parameters (wood_parameters.def). A preset may not list those ids (presetFromJson
// refuses them), so choosing a species never moves the rings of a fitted block.
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "params/parameter_schema.hpp"

namespace kerf {

inline constexpr int kPresetFormatVersion = 1;
inline constexpr const char* kPresetFormatName = "kerf-preset";

struct Preset {
  std::string id;           // file stem, lower case: "kuri"
  std::string name;         // "Japanese chestnut (kuri)"
  std::string latin;        // "Castanea crenata"
  std::string mokumeCode;   // "CN" (Mokume Table 1); empty for presets of other species
  std::string description;  // one line in wood terms
  nlohmann::json parameters = nlohmann::json::object();  // id -> value, only non-default values

  // The schema defaults, the preset's values on top, and the block-specific values of `base`
  // (presetKeptParameterIds()). Throws InputError if the result is out of range.
  WoodParameters applyTo(const WoodParameters& base) const;
  // The preset on top of the schema defaults alone.
  WoodParameters parametersOnDefaults() const;
};

// Ids of the parameters a preset keeps from the current parameters (and may not set): the schema's
// ParamScope::Block ones, in schema order.
std::span<const std::string_view> presetKeptParameterIds();

// Parses and checks one preset (format, version, fields, parameter ids and ranges). Throws InputError
// naming the offending field.
Preset presetFromJson(const nlohmann::json& json);
nlohmann::json presetToJson(const Preset& preset);

// The preset with this id, or nullptr.
const Preset* findPreset(std::span<const Preset> presets, std::string_view id);

}  // namespace kerf
