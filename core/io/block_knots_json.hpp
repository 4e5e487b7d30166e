#pragma once
// The knots of a block's growth field (field/block_knots.hpp) as JSON, the optional "knots" key of a
// .kerf file (projects without it have no knots):
//
//   "knots": [{"id": 0, "origin": [x, y, z], "direction": [x, y, z], "speed": 0.12}, ...]
//
// Block mm; "direction" need not be unit length (it is normalised when the model is built). Optional:
// "taper", "taper_age_years" (issue 19 item 2), "death_years" (a dead knot: the stem's age in years when
// the branch died; absent or null: alive). The global knot settings (smoothness, darkening,
// knots.stem_radius) are parameters (knots.*), not stored here.
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "field/block_knots.hpp"

namespace kerf {

nlohmann::json blockKnotsToJson(const std::vector<BlockKnot>& knots);
// Throws InputError naming the entry, e.g. "knots[1].speed must be a number", and refuses keys this
// Kerf does not know (an entry written by a newer Kerf).
std::vector<BlockKnot> blockKnotsFromJson(const nlohmann::json& json);

}  // namespace kerf
