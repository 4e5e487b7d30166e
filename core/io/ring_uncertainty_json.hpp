#pragma once
// How sure the fit is (field/ring_uncertainty.hpp) as JSON, the optional "ring_uncertainty" key of a .kerf
// file:
//
//   "ring_uncertainty": {"nodes": [nx, ny, nz], "sigma_mm": [...], "replicates": 8, "calibration": 1.0,
//                        "field": "9f3c..."}
//
// sigma_mm: nx * ny * nz values, x fastest, spanning the block corner to corner; field: the fingerprint
// of the field it belongs to (hex), so that a file whose field was edited elsewhere shows it as stale.
#include <nlohmann/json_fwd.hpp>

#include "field/ring_uncertainty.hpp"

namespace kerf {

nlohmann::json ringUncertaintyToJson(const RingUncertainty& uncertainty);
// Throws InputError naming the key, e.g. "ring_uncertainty.sigma_mm: 10 values for a grid of ...".
RingUncertainty ringUncertaintyFromJson(const nlohmann::json& json);

}  // namespace kerf
