#include "render/board_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <sstream>
#include <vector>

#include "util/error.hpp"
#include "util/number_list.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kTwoPi = 2.0f * kPi;

float radians(float deg) {
  return deg * (kPi / 180.0f);
}
float degrees(float rad) {
  return rad * (180.0f / kPi);
}

// Column-major rotations about the x, y, z axes (right-handed).
glm::mat3 rotX(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return glm::mat3(1, 0, 0, 0, c, s, 0, -s, c);
}
glm::mat3 rotY(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return glm::mat3(c, 0, -s, 0, 1, 0, s, 0, c);
}
glm::mat3 rotZ(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return glm::mat3(c, s, 0, -s, c, 0, 0, 0, 1);
}

// Board -> log with no rotation: board x = log x, board y = log z, board z = log -y.
const glm::mat3 kBase(1, 0, 0, 0, 0, 1, 0, -1, 0);

// A board whose face A looks along -outward (towards the pith) from the plane at `distance` along the
// horizontal direction `azimuth`, centred at height z.
Board facingPith(const LogModel& log, float azimuth, float distance, float z, glm::vec3 size) {
  Board b;
  b.size = size;
  b.rotationDeg = glm::vec3(0.0f, degrees(azimuth) - 90.0f, 0.0f);
  const glm::vec2 pith = log.stem.pithAt(z);
  const glm::vec2 out(std::cos(azimuth), std::sin(azimuth));
  const glm::vec2 c = pith + (distance + 0.5f * size.z) * out;
  b.center = glm::vec3(c.x, c.y, z);
  return b;
}

}  // namespace

glm::mat3 Board::axes() const {
  return kBase * rotY(radians(rotationDeg.y)) * rotX(radians(rotationDeg.x)) * rotZ(radians(rotationDeg.z));
}

Board parseBoard(const std::string& text) {
  const std::vector<float> v = parseNumberList(text, "--board");
  if (v.size() != 6 && v.size() != 9) {
    throw InputError(
        "--board takes 6 or 9 numbers: cx,cy,cz,sx,sy,sz[,rx,ry,rz] (centre in the log frame, "
        "size width,length,thickness in mm, rotations in degrees); got \"" +
        text + "\"");
  }
  Board b;
  b.center = glm::vec3(v[0], v[1], v[2]);
  b.size = glm::vec3(v[3], v[4], v[5]);
  if (v.size() == 9) b.rotationDeg = glm::vec3(v[6], v[7], v[8]);
  if (!(b.size.x > 0 && b.size.y > 0 && b.size.z > 0)) throw InputError("--board: the size must be positive");
  return b;
}

std::string formatBoard(const Board& b) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f", b.center.x, b.center.y,
                b.center.z, b.size.x, b.size.y, b.size.z, b.rotationDeg.x, b.rotationDeg.y, b.rotationDeg.z);
  return buf;
}

Board defaultBoard(const LogModel& log, float faceDistanceMm) {
  const glm::vec3 size(110.0f, 110.0f, 30.0f);
  const float z = knottiestHeight(log, 0.8f * size.y, faceDistanceMm);
  // The direction that most of this section's knots point to at the face's distance.
  float best = 0.0f;
  int bestCount = -1;
  for (int a = 0; a < 72; ++a) {
    const float phi = kTwoPi * static_cast<float>(a) / 72.0f;
    int count = 0;
    for (const Knot& k : log.knots) {
      if (std::abs(k.heightAt(faceDistanceMm) - z) > 0.5f * size.y) continue;
      float d = k.azimuthAt(faceDistanceMm) - phi;
      d -= kTwoPi * std::round(d / kTwoPi);
      if (std::abs(d) < radians(30.0f)) ++count;
    }
    if (count > bestCount) bestCount = count, best = phi;
  }
  return facingPith(log, best, faceDistanceMm, z, size);
}

Board boardAcrossKnot(const LogModel& log, int knot, float faceDistanceMm, glm::vec3 size) {
  if (knot < 0 || knot >= static_cast<int>(log.knots.size()))
    throw InputError("no knot " + std::to_string(knot));
  const Knot& k = log.knots[knot];
  return facingPith(log, k.azimuthAt(faceDistanceMm), faceDistanceMm, k.heightAt(faceDistanceMm), size);
}

Board boardAlongKnot(const LogModel& log, int knot, glm::vec3 size) {
  if (knot < 0 || knot >= static_cast<int>(log.knots.size()))
    throw InputError("no knot " + std::to_string(knot));
  const Knot& k = log.knots[knot];
  const float mid = 0.5f * size.x - 5.0f;  // the face spans from 5 mm behind the pith outward
  const float azimuth = k.azimuthAt(mid);
  const float z = k.heightAt(mid);
  Board b;
  b.size = size;
  // Board x along the knot's direction; face A (board +z) then has the normal (sin a, -cos a).
  b.rotationDeg = glm::vec3(0.0f, degrees(azimuth), 0.0f);
  const glm::vec2 out(std::cos(azimuth), std::sin(azimuth)), normal(std::sin(azimuth), -std::cos(azimuth));
  const glm::vec2 c = log.stem.pithAt(z) + mid * out - 0.5f * size.z * normal;
  b.center = glm::vec3(c.x, c.y, z);
  return b;
}

void checkBoardMeetsLog(const LogModel& log, const Board& board) {
  const Stem& stem = log.stem;
  const float reach = 0.5f * glm::length(board.size);  // the board lies inside this sphere
  glm::vec2 pithLo, pithHi;
  stem.pithRange(0.0f, stem.height(), pithLo, pithHi);
  const glm::vec2 centre(board.center.x, board.center.y);
  const float fromPith = glm::length(centre - glm::clamp(centre, pithLo, pithHi));
  const bool missesHeight = board.center.z + reach < 0.0f || board.center.z - reach > stem.height();
  if (!missesHeight && fromPith - reach <= stem.maxRadius()) return;
  std::ostringstream text;
  text << "the board (centre " << board.center.x << ", " << board.center.y << ", " << board.center.z
       << " mm) lies entirely outside the log: the stem spans heights 0 to " << stem.height()
       << " mm and reaches at most " << stem.maxRadius() << " mm from its pith";
  throw InputError(text.str());
}

BoardFaceLayout layoutBoardFace(const KnotField& field, const Board& board,
                                const BoardRenderOptions& options) {
  if (options.resolution < 1) throw InputError("the resolution must be at least 1 pixel");
  checkBoardMeetsLog(field.log(), board);
  BoardFaceLayout layout;
  const Block block = board.block();
  const FaceFrame frame = block.face(options.face);
  const float pxPerMm = static_cast<float>(options.resolution) / std::max(frame.widthMm, frame.heightMm);
  layout.size = block.faceImageSize(options.face, pxPerMm);
  checkImageSize(layout.size, "the image of the board's face " + std::string(1, faceLetter(options.face)));
  const glm::mat3 axes = board.axes();
  auto logPoint = [&](glm::vec2 imagePos) {
    return board.center + axes * block.imageToBlock(options.face, imagePos, layout.size);
  };
  layout.origin = logPoint(glm::vec2(0.0f));
  layout.stepX = logPoint(glm::vec2(1.0f, 0.0f)) - layout.origin;
  layout.stepY = logPoint(glm::vec2(0.0f, 1.0f)) - layout.origin;

  // Per board: the knots that can reach any point of the board (the box around its 8 corners).
  layout.cull = options.cull;
  if (options.cull) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    const glm::vec3 h = block.halfSize();
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 p =
          board.toLog(glm::vec3((c & 1) ? h.x : -h.x, (c & 2) ? h.y : -h.y, (c & 4) ? h.z : -h.z));
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    field.cull(lo, hi, field.allKnots(), layout.boardKnots);
  } else {
    layout.boardKnots.assign(field.allKnots().begin(), field.allKnots().end());
  }
  layout.tile = std::max(options.tileSize, 1);
  layout.tilesX = (layout.size.x + layout.tile - 1) / layout.tile;
  layout.tilesY = (layout.size.y + layout.tile - 1) / layout.tile;
  return layout;
}

glm::ivec4 BoardFaceLayout::tilePixels(int tx, int ty) const {
  const int x0 = tx * tile, y0 = ty * tile;
  return {x0, y0, std::min(x0 + tile, size.x), std::min(y0 + tile, size.y)};
}

void BoardFaceLayout::tileKnots(const KnotField& field, int tx, int ty, std::vector<int>& out) const {
  out.clear();
  if (!cull) {
    out = boardKnots;
    return;
  }
  // The box around the tile's four corners (the tile is a flat rectangle), padded against rounding.
  const glm::ivec4 r = tilePixels(tx, ty);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (int c = 0; c < 4; ++c) {
    const glm::vec3 p = toLog(glm::vec2((c & 1) ? r.z : r.x, (c & 2) ? r.w : r.y));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  field.cull(lo - glm::vec3(1e-3f), hi + glm::vec3(1e-3f), boardKnots, out);
}

Image renderBoardFace(const KnotField& field, const WoodColorMap& colors, const Board& board,
                      const BoardRenderOptions& options, BoardRenderStats* stats, const Progress& progress) {
  const BoardFaceLayout layout = layoutBoardFace(field, board, options);
  const glm::ivec2 size = layout.size;
  Image image(size.x, size.y, 3);
  std::atomic<long long> tileKnotSum{0}, inReachSum{0};
  parallelRows(
      layout.tilesY,
      [&](int ty) {
        std::vector<int> knots;
        long long knotSum = 0, reachSum = 0;
        for (int tx = 0; tx < layout.tilesX; ++tx) {
          layout.tileKnots(field, tx, ty, knots);
          const glm::ivec4 r = layout.tilePixels(tx, ty);
          const int x0 = r.x, y0 = r.y, x1 = r.z, y1 = r.w;
          knotSum += static_cast<long long>(knots.size());
          for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
              const KnotFieldSample s = field.evaluate(layout.toLog(glm::vec2(x + 0.5f, y + 0.5f)), knots);
              reachSum += s.knotsInReach;
              const glm::vec3 c = field.color(s, colors);
              float* px = image.pixel(x, y);
              px[0] = c.x, px[1] = c.y, px[2] = c.z;
            }
          }
        }
        tileKnotSum += knotSum;
        inReachSum += reachSum;
      },
      progress);
  if (stats) {
    stats->boardKnots = static_cast<int>(layout.boardKnots.size());
    stats->pixels = static_cast<std::size_t>(size.x) * size.y;
    stats->meanTileKnots =
        static_cast<double>(tileKnotSum) / (static_cast<double>(layout.tilesX) * layout.tilesY);
    stats->meanKnotsInReach = static_cast<double>(inReachSum) / static_cast<double>(stats->pixels);
  }
  return image;
}

}  // namespace kerf
