#pragma once
// Boards cut from a log, rendered on the CPU with the knot model (field/knot_field.hpp, docs/knots.md).
//
// A board is a block (Kerf block frame: x = width, y = length, z = thickness, docs/coordinates.md) placed in
// the log frame: with no rotation its length runs up the log (board +y = log +z), its width along log +x and
// its face A (board +z) looks towards log -y. Rotations, in degrees, turn it about its own axes: first rz
// about its thickness axis, then rx about its width axis, then ry about the log axis:
//   p_log = centre + Base * Ry(ry) * Rx(rx) * Rz(rz) * p_board.
// Rendering culls knots per board and per tile: only the knots that can reach a tile are evaluated there.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "field/knot_field.hpp"
#include "geometry/block.hpp"
#include "image/image.hpp"
#include "util/progress.hpp"

namespace kerf {

struct Board {
  glm::vec3 center{0.0f};                 // log frame, mm
  glm::vec3 size{100.0f, 100.0f, 40.0f};  // width, length, thickness, mm
  glm::vec3 rotationDeg{0.0f};            // rx, ry, rz (see above)

  glm::mat3 axes() const;  // columns: the board's x, y, z axes in the log frame
  glm::vec3 toLog(const glm::vec3& boardPoint) const { return center + axes() * boardPoint; }
  Block block() const { return Block(size); }
};

// "cx,cy,cz,sx,sy,sz[,rx,ry,rz]" (mm, degrees); throws InputError with the expected form.
Board parseBoard(const std::string& text);
std::string formatBoard(const Board& board);

// A flat-sawn board through the knottiest section of the log: 110 x 110 x 30 mm, its face A tangent to
// the rings at `faceDistanceMm` from the pith, turned to face the most knots of that section.
Board defaultBoard(const LogModel& log, float faceDistanceMm = 30.0f);

// A flat-sawn board whose face A (looking towards the pith) lies at `faceDistanceMm` from the pith across
// the given knot's direction there, centred on the knot: the knot is cut across its axis.
Board boardAcrossKnot(const LogModel& log, int knot, float faceDistanceMm, glm::vec3 size);
// A board whose face A is the radial plane through the pith and the given knot's axis (the knot is cut
// along its length), the face spanning from the pith outward.
Board boardAlongKnot(const LogModel& log, int knot, glm::vec3 size);

// Throws InputError unless the board can meet the log (issue 21: a board 1 km away rendered flat wood
// without a word). Conservative: refuses only a board whose bounding sphere misses the stem's bounding
// cylinder, so a board half out of the log (bark side) still renders.
void checkBoardMeetsLog(const LogModel& log, const Board& board);

struct BoardRenderOptions {
  FaceId face = FaceId::A;
  int resolution = 1200;  // pixels along the face's longer side
  bool cull = true;       // false: evaluate every knot at every pixel (the reference for the culling test)
  int tileSize = 16;      // pixels per tile side for the per-tile culling
};

struct BoardRenderStats {
  int boardKnots = 0;           // knots that survive the per-board culling
  double meanTileKnots = 0;     // mean knots per tile after per-tile culling
  double meanKnotsInReach = 0;  // mean knots per pixel whose window was non-zero
  std::size_t pixels = 0;
};

// Where a board face's pixels lie in the log and which knots can reach them: computed once and shared by
// the CPU renderer and its GLSL twin (gpu/gpu_board_renderer.*), so both sample the same points
// and keep the same knots.
struct BoardFaceLayout {
  glm::ivec2 size{0};                       // pixels
  glm::vec3 origin{0}, stepX{0}, stepY{0};  // the face is flat: log point = origin + x stepX + y stepY
  std::vector<int> boardKnots;  // the knots that can reach the board (all of them without culling)
  int tile = 16, tilesX = 0, tilesY = 0;
  bool cull = true;

  glm::vec3 toLog(glm::vec2 imagePos) const { return origin + imagePos.x * stepX + imagePos.y * stepY; }
  // The pixel range [x0, x1) x [y0, y1) of tile (tx, ty).
  glm::ivec4 tilePixels(int tx, int ty) const;
  // Replaces `out` by those of boardKnots that can reach tile (tx, ty) (all of them without culling).
  void tileKnots(const KnotField& field, int tx, int ty, std::vector<int>& out) const;
};
BoardFaceLayout layoutBoardFace(const KnotField& field, const Board& board,
                                const BoardRenderOptions& options);

// The face of `board` as an RGB image, `options.resolution` pixels along its longer side.
Image renderBoardFace(const KnotField& field, const WoodColorMap& colors, const Board& board,
                      const BoardRenderOptions& options, BoardRenderStats* stats = nullptr,
                      const Progress& progress = {});

}  // namespace kerf
