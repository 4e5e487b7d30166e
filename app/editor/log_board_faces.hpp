#pragma once
// The six faces of a board cut from a log, rendered on the CPU with the knot model (render/board_renderer),
// as the editor's faces view and 3D view show them when the document has a log. Runs on any thread.
#include <QImage>
#include <array>

#include "io/project_log.hpp"
#include "params/parameter_schema.hpp"
#include "util/progress.hpp"

namespace kerf {

// The log's own colour map, else one from the parameters (rings of growth.ring_width, heartwood and
// sapwood colours).
WoodColorMap logColorMap(const LogModel& log, const WoodParameters& params);

// Faces A..F at `pxPerMm` (at least 8 px per side, at most 1600 px along the board's longest side); the
// log's own colour map, else one from the parameters.
// Throws Cancelled when progress.stop is requested.
std::array<QImage, 6> renderLogBoardFaces(const ProjectLog& log, const WoodParameters& params, float pxPerMm,
                                          const Progress& progress = {});

}  // namespace kerf
