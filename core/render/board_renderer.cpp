#include "render/board_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <numbers>
#include <sstream>
#include <vector>

#include "util/error.hpp"
#include "util/parallel.hpp"

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
  std::vector<float> v;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stof(item, &used));
      if (used != item.size() && item.find_first_not_of(" ", used) != std::string::npos)
        throw std::invalid_argument("");
    } catch (const std::exception&) {
      v.clear();
      break;
    }
  }
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
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(b.center[i]) || !std::isfinite(b.size[i]) || !std::isfinite(b.rotationDeg[i])) {
      throw InputError("--board: every number must be finite");
    }
  }
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

Image renderBoardFace(const KnotField& field, const WoodColorMap& colors, const Board& board,
                      const BoardRenderOptions& options, BoardRenderStats* stats, const Progress& progress) {
  if (options.resolution < 1) throw InputError("the resolution must be at least 1 pixel");
  const Block block = board.block();
  const FaceFrame frame = block.face(options.face);
  const float pxPerMm = static_cast<float>(options.resolution) / std::max(frame.widthMm, frame.heightMm);
  const glm::ivec2 size = block.faceImageSize(options.face, pxPerMm);
  Image image(size.x, size.y, 3);
  const glm::mat3 axes = board.axes();
  // The face is flat: the log point is affine in the image position (one corner plus two steps).
  const glm::vec3 origin = board.center + axes * block.imageToBlock(options.face, glm::vec2(0.0f), size);
  const glm::vec3 stepX =
      board.center + axes * block.imageToBlock(options.face, glm::vec2(1.0f, 0.0f), size) - origin;
  const glm::vec3 stepY =
      board.center + axes * block.imageToBlock(options.face, glm::vec2(0.0f, 1.0f), size) - origin;
  auto toLog = [&](glm::vec2 imagePos) { return origin + imagePos.x * stepX + imagePos.y * stepY; };

  // Per board: the knots that can reach any point of the board.
  std::vector<int> boardKnots;
  {
    glm::vec3 lo(1e30f), hi(-1e30f);
    const glm::vec3 h = block.halfSize();
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 p =
          board.toLog(glm::vec3((c & 1) ? h.x : -h.x, (c & 2) ? h.y : -h.y, (c & 4) ? h.z : -h.z));
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    if (options.cull) {
      field.cull(lo, hi, field.allKnots(), boardKnots);
    } else {
      boardKnots.assign(field.allKnots().begin(), field.allKnots().end());
    }
  }

  const int tile = std::max(options.tileSize, 1);
  const int tilesX = (size.x + tile - 1) / tile, tilesY = (size.y + tile - 1) / tile;
  std::atomic<long long> tileKnotSum{0}, inReachSum{0};
  parallelRows(
      tilesY,
      [&](int ty) {
        std::vector<int> tileKnots;
        long long knotSum = 0, reachSum = 0;
        for (int tx = 0; tx < tilesX; ++tx) {
          const int x0 = tx * tile, y0 = ty * tile;
          const int x1 = std::min(x0 + tile, size.x), y1 = std::min(y0 + tile, size.y);
          std::span<const int> knots = boardKnots;
          if (options.cull) {
            // Per tile: the box around the tile's four corners (the tile is a flat rectangle).
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (int c = 0; c < 4; ++c) {
              const glm::vec3 p = toLog(glm::vec2((c & 1) ? x1 : x0, (c & 2) ? y1 : y0));
              lo = glm::min(lo, p);
              hi = glm::max(hi, p);
            }
            tileKnots.clear();
            field.cull(lo - glm::vec3(1e-3f), hi + glm::vec3(1e-3f), boardKnots, tileKnots);
            knots = tileKnots;
          }
          knotSum += static_cast<long long>(knots.size());
          for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
              const KnotFieldSample s = field.evaluate(toLog(glm::vec2(x + 0.5f, y + 0.5f)), knots);
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
    stats->boardKnots = static_cast<int>(boardKnots.size());
    stats->pixels = static_cast<std::size_t>(size.x) * size.y;
    stats->meanTileKnots = static_cast<double>(tileKnotSum) / (static_cast<double>(tilesX) * tilesY);
    stats->meanKnotsInReach = static_cast<double>(inReachSum) / static_cast<double>(stats->pixels);
  }
  return image;
}

}  // namespace kerf
