#include "io/block_knots_json.hpp"

#include <nlohmann/json.hpp>

#include "io/json_file.hpp"
#include "util/error.hpp"
#include "util/parse_number.hpp"

namespace kerf {

using nlohmann::json;

namespace {

glm::vec3 readVec3(const json& value, const std::string& what) {
  if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
      !value[2].is_number())
    throw InputError(what + " must be [x, y, z] in mm, got " + describeJson(value));
  return {checkedNumber<float>(value[0].get<double>(), what),
          checkedNumber<float>(value[1].get<double>(), what),
          checkedNumber<float>(value[2].get<double>(), what)};
}

}  // namespace

json blockKnotsToJson(const std::vector<BlockKnot>& knots) {
  json out = json::array();
  for (const BlockKnot& k : knots) {
    json knot = {{"id", k.id},
                 {"origin", {k.origin.x, k.origin.y, k.origin.z}},
                 {"direction", {k.direction.x, k.direction.y, k.direction.z}},
                 {"speed", k.speed}};
    if (k.taper != BlockKnot{}.taper || k.taperAge != BlockKnot{}.taperAge) {  // a plain cone as before
      knot["taper"] = k.taper;
      knot["taper_age_years"] = k.taperAge;
    }
    if (k.dead()) knot["death_years"] = k.deathTime;  // absent: alive, as every knot before issue 19
    out.push_back(std::move(knot));
  }
  return out;
}

std::vector<BlockKnot> blockKnotsFromJson(const json& in) {
  if (!in.is_array()) throw InputError("knots must be a list of knots, got " + describeJson(in));
  if (in.size() > kMaxBlockKnots)  // every knot is evaluated at every pixel (field/block_knots.hpp)
    throw InputError("knots holds " + std::to_string(in.size()) + " knots; Kerf takes at most " +
                     std::to_string(kMaxBlockKnots) + " knots in a block (each is evaluated at every pixel)");
  std::vector<BlockKnot> knots;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const std::string what = "knots[" + std::to_string(i) + "]";
    const json& entry = in[i];
    if (!entry.is_object()) throw InputError(what + " must be an object, got " + describeJson(entry));
    for (const auto& [key, value] : entry.items()) {
      if (key != "id" && key != "origin" && key != "direction" && key != "speed" && key != "taper" &&
          key != "taper_age_years" && key != "death_years")
        throw InputError(what + " has an unknown key \"" + key +
                         "\" (written by a newer Kerf? known: id, origin, direction, speed, taper, "
                         "taper_age_years, death_years)");
    }
    for (const char* key : {"id", "origin", "direction", "speed"})
      if (!entry.contains(key)) throw InputError(what + " lacks \"" + key + "\"");
    BlockKnot knot;
    if (!entry["id"].is_number()) throw InputError(what + ".id must be a whole number");
    knot.id = checkedNumber<int>(entry["id"].get<double>(), what + ".id");
    knot.origin = readVec3(entry["origin"], what + ".origin");
    knot.direction = readVec3(entry["direction"], what + ".direction");
    if (!entry["speed"].is_number()) throw InputError(what + ".speed must be a number");
    knot.speed = checkedNumber<float>(entry["speed"].get<double>(), what + ".speed");
    for (const auto& [key, member] :
         {std::pair{"taper", &knot.taper}, std::pair{"taper_age_years", &knot.taperAge}}) {
      if (!entry.contains(key)) continue;
      if (!entry[key].is_number()) throw InputError(what + "." + key + " must be a number");
      *member = checkedNumber<float>(entry[key].get<double>(), what + "." + key);
    }
    if (entry.contains("death_years") && !entry["death_years"].is_null()) {
      // The stem's age in years when the branch died; null or absent: alive.
      if (!entry["death_years"].is_number())
        throw InputError(what +
                         ".death_years must be a number of years from the pith (or null: alive), got " +
                         describeJson(entry["death_years"]));
      knot.deathTime = checkedNumber<float>(entry["death_years"].get<double>(), what + ".death_years");
    }
    validate(knot, what);
    knots.push_back(knot);
  }
  return knots;
}

}  // namespace kerf
