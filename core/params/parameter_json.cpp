#include "params/parameter_json.hpp"

#include <string>

#include "util/error.hpp"
#include "util/json_text.hpp"

namespace kerf {
using nlohmann::json;

json parametersToJson(const WoodParameters& params) {
  json out = json::object();
  const auto schema = parameterSchema();
  for (std::size_t i = 0; i < schema.size(); ++i) {
    const auto values = params.components(i);
    if (values.size() == 1) {
      out[std::string(schema[i].id)] =
          schema[i].kind == ParamKind::Integer ? json(static_cast<long>(values[0])) : json(values[0]);
    } else {
      out[std::string(schema[i].id)] = json::array({values[0], values[1], values[2]});
    }
  }
  return out;
}

WoodParameters parametersFromJson(const json& in) {
  if (!in.is_object()) throw InputError("\"parameters\" must be an object of id: value pairs");
  WoodParameters params;
  for (const auto& [id, value] : in.items()) {
    const auto index = parameterIndex(id);
    if (!index) throw InputError("unknown parameter \"" + id + "\" (see `kerf-cli params` for the list)");
    const auto target = params.components(*index);
    if (target.size() == 1) {
      target[0] = readJsonNumber(value, "parameter " + id);
    } else {
      const glm::vec3 v = readJsonVec3(value, "parameter " + id);
      target[0] = v.x, target[1] = v.y, target[2] = v.z;
    }
  }
  validate(params);
  return params;
}

}  // namespace kerf
