#include "io/ring_uncertainty_json.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "util/error.hpp"
#include "util/json_text.hpp"
#include "util/parse_number.hpp"

namespace kerf {

using nlohmann::json;

json ringUncertaintyToJson(const RingUncertainty& u) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(u.field));
  return {{"nodes", {u.nodes.x, u.nodes.y, u.nodes.z}},
          {"sigma_mm", u.sigmaMm},
          {"replicates", u.replicates},
          {"calibration", u.calibration},
          {"field", hex}};
}

RingUncertainty ringUncertaintyFromJson(const json& in) {
  if (!in.is_object()) throw InputError("\"ring_uncertainty\" must be an object");
  for (const auto& [key, value] : in.items())
    if (key != "nodes" && key != "sigma_mm" && key != "replicates" && key != "calibration" && key != "field")
      throw InputError("ring_uncertainty: unknown key \"" + key + "\"");
  RingUncertainty u;
  const json& nodes = in.value("nodes", json());
  if (!nodes.is_array() || nodes.size() != 3) throw InputError("ring_uncertainty.nodes must be [nx, ny, nz]");
  for (int a = 0; a < 3; ++a)
    u.nodes[a] = checkedNumber<int>(readJsonNumber(nodes[a], "ring_uncertainty.nodes"),
                                    "ring_uncertainty.nodes", 2, 256);
  const json& sigma = in.value("sigma_mm", json());
  if (!sigma.is_array()) throw InputError("ring_uncertainty.sigma_mm must be a list of numbers");
  u.sigmaMm.reserve(sigma.size());
  for (const json& v : sigma) u.sigmaMm.push_back(readJsonNumber(v, "ring_uncertainty.sigma_mm"));
  u.replicates =
      checkedNumber<int>(readJsonNumber(in.value("replicates", json(0)), "ring_uncertainty.replicates"),
                         "ring_uncertainty.replicates", 0, 1000);
  u.calibration = readJsonNumber(in.value("calibration", json(1.0)), "ring_uncertainty.calibration");
  const json& field = in.value("field", json(""));
  if (!field.is_string()) throw InputError("ring_uncertainty.field must be a hex string");
  const std::string hex = field.get<std::string>();
  if (hex.empty() || hex.size() > 16 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
    throw InputError("ring_uncertainty.field must be a hex string of up to 16 digits");
  u.field = std::stoull(hex, nullptr, 16);
  u.validate();
  return u;
}

}  // namespace kerf
