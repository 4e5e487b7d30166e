#pragma once
// The wood of a board cut from a log, at any point of the board: what the editor's 3D view and cut
// panel evaluate per fragment in log mode (shaders/board_wood.glsl), and its CPU reference.
//
// Per fragment there are no screen tiles to cull knots by, so the board is covered by a coarse 3D grid
// (KnotCellGrid, at most 16 cells per side) and each cell lists the knots that can reach it: the board
// frame box of the cell, padded, is mapped into the log and KnotField::cull keeps the knots that may
// reach that box's bounding box. The rotated box lies inside that bounding box, so a knot that is not
// listed contributes exactly nothing to any point of the cell (docs/knots.md, "Culling"), and the
// evaluation over a cell's list equals the evaluation over all knots, bit for bit.
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "field/knot_field.hpp"
#include "geometry/cut_plane.hpp"
#include "image/image.hpp"
#include "render/board_renderer.hpp"
#include "util/progress.hpp"

namespace kerf {

struct BoardWood {
  std::shared_ptr<const KnotField> field;
  std::shared_ptr<const WoodColorMap> colors;
  Board board;
};

// The colour at a board point (board frame, mm), evaluating every knot of the log (the reference).
glm::vec3 boardWoodColor(const BoardWood& wood, const glm::vec3& boardPoint);

struct KnotCellGrid {
  glm::ivec3 cells{1};
  // Per cell (x fastest, then y, then z): the first entry in `list` and the number of entries.
  std::vector<glm::ivec2> ranges;
  std::vector<int> list;       // knot indices into the log's knots, ascending per cell
  std::size_t boardKnots = 0;  // knots that can reach the board at all

  // The cell of a board point (clamped into the grid): the same arithmetic as shaders/board_wood.glsl.
  glm::ivec3 cellOf(const glm::vec3& boardPoint, const glm::vec3& boardSize) const;
  std::size_t cellIndex(glm::ivec3 cell) const {
    return (static_cast<std::size_t>(cell.z) * cells.y + cell.y) * cells.x + cell.x;
  }
  double meanKnotsPerCell() const;
};

// Cells per axis: about cubic cells, `maxCellsPerSide` along the board's longest side.
glm::ivec3 knotGridCells(const glm::vec3& boardSize, int maxCellsPerSide = 16);
KnotCellGrid buildKnotCellGrid(const KnotField& field, const Board& board, glm::ivec3 cells);

// The cut surface of `plane` (board frame) through the board, on the CPU: RGBA in the layout of
// renderCut (render/renderers.hpp; one sample per pixel, transparent outside the board), the picture
// the editor's cut panel draws in log mode. Knots culled by the grid (no pixel changes).
// Throws InputError when the plane misses the board.
Image renderBoardCut(const BoardWood& wood, const CutPlane& plane, float pxPerMm,
                     const Progress& progress = {});

}  // namespace kerf
