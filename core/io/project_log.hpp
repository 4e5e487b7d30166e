#pragma once
// A log and the board placed in it, as a project carries them (docs/knots.md, docs/editor.md): when a
// project has one, the editor's faces are the board's faces rendered with the knot model. Saved under the
// optional project key "log": {"model": <the .kerflog JSON>, "board": {...}}; projects without it load
// unchanged.
#include <nlohmann/json_fwd.hpp>

#include "field/log_model.hpp"
#include "render/board_renderer.hpp"

namespace kerf {

struct ProjectLog {
  LogModel log;
  Board board;
};

nlohmann::json boardToJson(const Board& board);
Board boardFromJson(const nlohmann::json& json);  // throws InputError naming the field
nlohmann::json projectLogToJson(const ProjectLog& log);
ProjectLog projectLogFromJson(const nlohmann::json& json);  // throws InputError

}  // namespace kerf
