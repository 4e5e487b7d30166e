#pragma once
// The parameters as JSON, as projects and presets store them:
// {"growth.ring_width": 3.0, "color.earlywood": [r,g,b], ...}, every id of the schema.
#include <nlohmann/json_fwd.hpp>

#include "params/parameter_schema.hpp"

namespace kerf {

nlohmann::json parametersToJson(const WoodParameters& params);
// Missing parameters take their defaults; unknown ids, NaNs and out-of-range values are refused
// (InputError naming the parameter).
WoodParameters parametersFromJson(const nlohmann::json& json);

}  // namespace kerf
