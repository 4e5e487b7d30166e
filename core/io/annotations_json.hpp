#pragma once
// The annotations of a project (core/rings/annotations.hpp) as JSON, the "annotations" key of a .kerf
// file (optional: projects without it have no annotations):
//
//   {"units": "face_mm",
//    "traces": [{"face": "A", "points": [[u, v], ...], "year": 3, "origin": "drawn"}, ...],
//    "knots":  [{"knot": 0, "face": "C", "point": [u, v], "accuracy_mm": 1, "released": false}, ...]}
//
// "year" is optional (an unnumbered trace); "origin" is "drawn" or "detected" (default "drawn"); a knot
// mark's "accuracy_mm" (0.05-50, default 1) and "released" (default false) are written only when not
// the default.
// Points are face millimetres (docs/coordinates.md, "Annotations").
#include <nlohmann/json_fwd.hpp>

#include "rings/annotations.hpp"

namespace kerf {

nlohmann::json annotationsToJson(const Annotations& annotations);
// Throws InputError naming the field, e.g. "annotations.traces[2].points[5] must be [u, v] ...". Points
// must be finite and not far outside their face of `block` (more than the face's own size beyond an
// edge: a sign of pixels written where mm are expected); a little outside is kept.
Annotations annotationsFromJson(const nlohmann::json& json, const Block& block);

}  // namespace kerf
