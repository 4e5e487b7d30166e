#include "render/board_wood.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <span>

#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

// Board-frame padding of a cell's box: covers the float rounding of the GPU's board -> log transform
// and of the cell index, and fragments a hair outside the board (the cut surface's edges).
constexpr float kCellPadMm = 0.05f;

}  // namespace

glm::vec3 boardWoodColor(const BoardWood& wood, const glm::vec3& boardPoint) {
  return wood.field->color(wood.field->evaluate(wood.board.toLog(boardPoint)), *wood.colors);
}

glm::ivec3 KnotCellGrid::cellOf(const glm::vec3& p, const glm::vec3& size) const {
  const glm::vec3 u = glm::floor((p / size + 0.5f) * glm::vec3(cells));
  return glm::clamp(glm::ivec3(u), glm::ivec3(0), cells - 1);
}

double KnotCellGrid::meanKnotsPerCell() const {
  return ranges.empty() ? 0.0 : static_cast<double>(list.size()) / static_cast<double>(ranges.size());
}

glm::ivec3 knotGridCells(const glm::vec3& size, int maxCellsPerSide) {
  const float cell = std::max({size.x, size.y, size.z}) / static_cast<float>(std::max(maxCellsPerSide, 1));
  glm::ivec3 cells;
  for (int i = 0; i < 3; ++i)
    cells[i] = std::clamp(static_cast<int>(std::ceil(size[i] / cell - 1e-3f)), 1, maxCellsPerSide);
  return cells;
}

KnotCellGrid buildKnotCellGrid(const KnotField& field, const Board& board, glm::ivec3 cells) {
  KnotCellGrid grid;
  grid.cells = glm::max(cells, glm::ivec3(1));
  const glm::vec3 h = 0.5f * board.size;
  const glm::vec3 step = board.size / glm::vec3(grid.cells);
  const auto logBox = [&](glm::vec3 lo, glm::vec3 hi, glm::vec3& outLo, glm::vec3& outHi) {
    outLo = glm::vec3(1e30f), outHi = glm::vec3(-1e30f);
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 p =
          board.toLog(glm::vec3((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z));
      outLo = glm::min(outLo, p);
      outHi = glm::max(outHi, p);
    }
  };
  glm::vec3 lo, hi;
  logBox(-h - kCellPadMm, h + kCellPadMm, lo, hi);
  std::vector<int> boardKnots;
  field.cull(lo, hi, field.allKnots(), boardKnots);
  grid.boardKnots = boardKnots.size();
  grid.ranges.resize(static_cast<std::size_t>(grid.cells.x) * grid.cells.y * grid.cells.z);
  std::vector<int> knots;
  for (int z = 0; z < grid.cells.z; ++z)
    for (int y = 0; y < grid.cells.y; ++y)
      for (int x = 0; x < grid.cells.x; ++x) {
        const glm::ivec3 c(x, y, z);
        // Edge cells reach past the board by the padding too, as the clamped cell index does.
        const glm::vec3 cellLo = -h + glm::vec3(c) * step - kCellPadMm;
        const glm::vec3 cellHi = -h + glm::vec3(c + 1) * step + kCellPadMm;
        logBox(cellLo, cellHi, lo, hi);
        knots.clear();
        field.cull(lo, hi, boardKnots, knots);
        grid.ranges[grid.cellIndex(c)] =
            glm::ivec2(static_cast<int>(grid.list.size()), static_cast<int>(knots.size()));
        grid.list.insert(grid.list.end(), knots.begin(), knots.end());
      }
  return grid;
}

Image renderBoardCut(const BoardWood& wood, const CutPlane& plane, float pxPerMm, const Progress& progress) {
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("pixels per mm must be a positive number");
  const Block block = wood.board.block();
  const auto bounds = plane.boundsInBlock(block);
  if (!bounds) throw InputError("the cut plane does not pass through the board");
  const glm::vec2 extent = bounds->max - bounds->min;
  const int width = pixelsAlong(std::ceil(double(extent.x) * pxPerMm - 1e-3));
  const int height = pixelsAlong(std::ceil(double(extent.y) * pxPerMm - 1e-3));
  checkImageSize({width, height}, "the image of the cut", pxPerMm);
  const KnotCellGrid grid = buildKnotCellGrid(*wood.field, wood.board, knotGridCells(wood.board.size));
  Image image(width, height, 4);
  parallelRows(
      height,
      [&](int y) {
        for (int x = 0; x < width; ++x) {
          // Image right = plane right, image down = plane -up; the top-left pixel is at (min.x, max.y).
          const glm::vec2 planePos(bounds->min.x + (x + 0.5f) / pxPerMm,
                                   bounds->max.y - (y + 0.5f) / pxPerMm);
          const glm::vec3 p = plane.toBlock(planePos);
          float* px = image.pixel(x, y);
          if (!block.contains(p)) {
            px[0] = px[1] = px[2] = px[3] = 0.0f;
            continue;
          }
          const glm::ivec2 range = grid.ranges[grid.cellIndex(grid.cellOf(p, wood.board.size))];
          const std::span<const int> knots(grid.list.data() + range.x, static_cast<std::size_t>(range.y));
          const glm::vec3 c =
              wood.field->color(wood.field->evaluate(wood.board.toLog(p), knots), *wood.colors);
          px[0] = c.x, px[1] = c.y, px[2] = c.z, px[3] = 1.0f;
        }
      },
      progress);
  return image;
}

}  // namespace kerf
