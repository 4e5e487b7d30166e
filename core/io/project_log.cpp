#include "io/project_log.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/log_data_import.hpp"
#include "util/error.hpp"
#include "util/parse_number.hpp"

namespace kerf {

using nlohmann::json;

namespace {

json vec3(const glm::vec3& v) {
  return json::array({v.x, v.y, v.z});
}

glm::vec3 readVec3(const json& in, const char* key) {
  const std::string what = std::string("log.board.") + key;
  if (!in.contains(key)) throw InputError(what + " is missing");
  const json& v = in.at(key);
  if (!v.is_array() || v.size() != 3) throw InputError(what + " must be [x, y, z]");
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number()) throw InputError(what + " must be numbers");
    out[i] = checkedNumber<float>(v[i].get<double>(), what);
  }
  return out;
}

}  // namespace

json boardToJson(const Board& board) {
  return {{"center_mm", vec3(board.center)},
          {"size_mm", vec3(board.size)},
          {"rotation_deg", vec3(board.rotationDeg)}};
}

Board boardFromJson(const json& in) {
  if (!in.is_object()) throw InputError("log.board must be an object");
  Board board;
  board.center = readVec3(in, "center_mm");
  board.size = readVec3(in, "size_mm");
  if (in.contains("rotation_deg")) board.rotationDeg = readVec3(in, "rotation_deg");
  if (!(board.size.x > 0 && board.size.y > 0 && board.size.z > 0))
    throw InputError("log.board.size_mm must be positive");
  return board;
}

json projectLogToJson(const ProjectLog& log) {
  return {{"model", logToJson(log.log)}, {"board", boardToJson(log.board)}};
}

ProjectLog projectLogFromJson(const json& in) {
  if (!in.is_object() || !in.contains("model") || !in.contains("board"))
    throw InputError("\"log\" needs \"model\" (a Kerf log) and \"board\"");
  return {logFromJson(in.at("model"), "the project's log"), boardFromJson(in.at("board"))};
}

}  // namespace kerf
