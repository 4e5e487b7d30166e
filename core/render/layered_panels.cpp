#include "render/layered_panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr int kTile = 16;
constexpr int kMaxLamellasPerLayer = 10000;  // 100 m of 10 mm boards
constexpr float kMinPanelSideMm = 0.01f;     // a panel, layer or ply thinner than this is no panel

// Every side from kMinPanelSideMm to kMaxBlockSideMm: a 1e-30 mm panel made a pixel count overflow.
void checkPanelSize(glm::vec3 size, const char* what) {
  for (int i = 0; i < 3; ++i)
    if (!(size[i] >= kMinPanelSideMm && size[i] <= kMaxBlockSideMm)) {
      char text[200];
      std::snprintf(text, sizeof text, "%s: the panel size %g x %g x %g mm is outside %g .. %g mm a side",
                    what, size.x, size.y, size.z, kMinPanelSideMm, kMaxBlockSideMm);
      throw InputError(text);
    }
}

// Renders an image whose pixel centres map to log points through `sample` (image position -> log point
// and shade). Per 16 x 16 tile, only the knots that can reach the box around the tile's own log points are
// evaluated, which changes no pixel (KnotField::cull) whatever the mapping.
template <class Sample>
Image renderMapped(const KnotField& field, const WoodColorMap& colors, glm::ivec2 size, const Sample& sample,
                   const Progress& progress) {
  Image image(size.x, size.y, 3);
  const int tilesX = (size.x + kTile - 1) / kTile, tilesY = (size.y + kTile - 1) / kTile;
  parallelRows(
      tilesY,
      [&](int ty) {
        std::vector<int> knots;
        std::vector<PanelSample> samples(kTile * kTile);
        for (int tx = 0; tx < tilesX; ++tx) {
          const int x0 = tx * kTile, y0 = ty * kTile;
          const int x1 = std::min(x0 + kTile, size.x), y1 = std::min(y0 + kTile, size.y);
          glm::vec3 lo(1e30f), hi(-1e30f);
          for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
              const PanelSample s = sample(glm::vec2(x + 0.5f, y + 0.5f));
              samples[(y - y0) * kTile + (x - x0)] = s;
              lo = glm::min(lo, s.logPoint);
              hi = glm::max(hi, s.logPoint);
            }
          }
          knots.clear();
          field.cull(lo - glm::vec3(1e-3f), hi + glm::vec3(1e-3f), field.allKnots(), knots);
          for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
              const PanelSample& s = samples[(y - y0) * kTile + (x - x0)];
              const glm::vec3 c = s.shade * field.color(field.evaluate(s.logPoint, knots), colors);
              float* px = image.pixel(x, y);
              px[0] = c.x, px[1] = c.y, px[2] = c.z;
            }
          }
        }
      },
      progress);
  return image;
}

// A panel face's pixels (as renderBoardFace lays them out) mapped through `map(panelPoint, jointMm)`.
template <class Map>
Image renderPanelFace(const KnotField& field, const WoodColorMap& colors, glm::vec3 panelSize, FaceId face,
                      int resolution, const Map& map, const Progress& progress) {
  if (resolution < 1) throw InputError("the resolution must be at least 1 pixel");
  const Block block(panelSize);
  const FaceFrame frame = block.face(face);
  const float pxPerMm = static_cast<float>(resolution) / std::max(frame.widthMm, frame.heightMm);
  const glm::ivec2 size = block.faceImageSize(face, pxPerMm);
  checkImageSize(size, "the image of the panel's face " + std::string(1, faceLetter(face)));
  const float jointMm = std::max(0.35f, 0.6f / pxPerMm);  // stays visible, but never wider than needed
  return renderMapped(
      field, colors, size, [&](glm::vec2 pos) { return map(block.imageToBlock(face, pos, size), jointMm); },
      progress);
}

}  // namespace

float VeneerPeel::radiusAt(float u) const {
  return std::sqrt(std::max(0.0f, startRadiusMm * startRadiusMm - thicknessMm * u / kPi));
}

float VeneerPeel::angleAt(float u) const {
  return 2.0f * kPi * (startRadiusMm - radiusAt(u)) / thicknessMm;
}

float VeneerPeel::lengthToCore(float coreRadiusMm) const {
  return kPi * (startRadiusMm * startRadiusMm - coreRadiusMm * coreRadiusMm) / thicknessMm;
}

glm::vec3 VeneerPeel::toLog(float u, float v, float depthMm) const {
  const float r = radiusAt(u) - depthMm;
  const float theta = startAzimuthRad + angleAt(u);
  return {axis.x + r * std::cos(theta), axis.y + r * std::sin(theta), startHeightMm + v};
}

VeneerPeel defaultPeel(const LogModel& log, float thicknessMm, float startHeightMm) {
  if (!(thicknessMm > 0.0f)) throw InputError("the veneer thickness must be > 0");
  VeneerPeel peel;
  peel.axis = log.stem.pithAt(0.5f * log.stem.height());
  peel.startRadiusMm = 0.92f * log.stem.minRadius();
  peel.thicknessMm = thicknessMm;
  peel.startHeightMm = startHeightMm;
  return peel;
}

void CltPanel::locate(const glm::vec3& p, int& layer, int& lamella, glm::vec3& q) const {
  const float t = layerThickness();
  layer = std::clamp(static_cast<int>(std::floor((p.z + 0.5f * size.z) / t)), 0, layers - 1);
  const float zl = p.z - (-0.5f * size.z + (static_cast<float>(layer) + 0.5f) * t);
  const bool alongLength = grainAlongLength(layer);
  // A cross layer is the long layer turned 90 degrees about z: (x, y) -> (y, -x), a proper rotation.
  const float across = alongLength ? p.x : p.y, along = alongLength ? p.y : -p.x;
  const float extent = alongLength ? size.x : size.y;
  const int count = static_cast<int>(lamellas[layer].size());
  lamella = std::clamp(static_cast<int>(std::floor((across + 0.5f * extent) / lamellaWidthMm)), 0, count - 1);
  const float centre = -0.5f * extent + (static_cast<float>(lamella) + 0.5f) * lamellaWidthMm;
  q = glm::vec3(across - centre, along, zl);
}

PanelSample CltPanel::map(const glm::vec3& p, float jointMm) const {
  int layer = 0, lamella = 0;
  glm::vec3 q;
  locate(p, layer, lamella, q);
  PanelSample s{lamellas[layer][lamella].toLog(q), shades[layer][lamella]};
  if (jointMm > 0.0f) {
    const int count = static_cast<int>(lamellas[layer].size());
    const bool sideInside = q.x < 0.0f ? lamella > 0 : lamella < count - 1;
    const bool layerInside = q.z < 0.0f ? layer > 0 : layer < layers - 1;
    const float toSide = 0.5f * lamellaWidthMm - std::abs(q.x),
                toLayer = 0.5f * layerThickness() - std::abs(q.z);
    if ((sideInside && toSide < jointMm) || (layerInside && toLayer < jointMm)) s.shade *= jointShade;
  }
  return s;
}

CltPanel makeCltPanel(const LogModel& log, glm::vec3 size, int layers, float lamellaWidth,
                      std::uint32_t seed) {
  if (layers < 1 || !(lamellaWidth > 0.0f) || !(size.x > 0 && size.y > 0 && size.z > 0))
    throw InputError("CLT: at least 1 layer, a positive lamella width and a positive panel size");
  checkPanelSize(size, "CLT");
  // The lamella count in double, bounded before anything is allocated: a 1e-30 mm (or 1e-6 mm) lamella
  // would ask for more boards than memory holds, and 1e30 does not fit an int (issue 21).
  const double lamellasPerLayer = std::ceil(double(std::max(size.x, size.y)) / lamellaWidth);
  if (!(lamellasPerLayer <= kMaxLamellasPerLayer) || !(size.z / layers >= kMinPanelSideMm)) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "CLT: %g mm lamellas in a %g x %g mm panel of %d layers would make %.3g lamellas a layer, "
                  "%g mm thick; Kerf makes up to %d lamellas a layer, at least %g mm thick",
                  lamellaWidth, size.x, size.y, layers, lamellasPerLayer, size.z / layers,
                  kMaxLamellasPerLayer, kMinPanelSideMm);
    throw InputError(text);
  }
  CltPanel panel;
  panel.size = size;
  panel.layers = layers;
  panel.lamellaWidthMm = lamellaWidth;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float t = panel.layerThickness(), height = log.stem.height(), rMin = log.stem.minRadius();
  for (int layer = 0; layer < layers; ++layer) {
    const bool alongLength = panel.grainAlongLength(layer);
    const float extent = alongLength ? size.x : size.y, length = alongLength ? size.y : size.x;
    const int count = static_cast<int>(std::ceil(extent / lamellaWidth - 1e-4f));
    std::vector<Board> boards;
    std::vector<float> shades;
    for (int j = 0; j < count; ++j) {
      Board b;
      b.size = glm::vec3(lamellaWidth, length, t);
      const float margin = 0.5f * length + 10.0f;
      const float z = height > 2.0f * margin ? margin + (height - 2.0f * margin) * unit(rng) : 0.5f * height;
      const float azimuth = 2.0f * kPi * unit(rng);
      // Flat-sawn, face A towards the pith, the whole cross-section inside the stem where it fits.
      const float dMin = 0.5f * t + 0.05f * rMin;
      const float reach = 0.95f * rMin, halfWidth = 0.5f * lamellaWidth;
      const float dMax =
          std::max(dMin, std::sqrt(std::max(0.0f, reach * reach - halfWidth * halfWidth)) - 0.5f * t);
      const float d = dMin + (dMax - dMin) * unit(rng);
      b.rotationDeg = glm::vec3(0.0f, azimuth * 180.0f / kPi, 0.0f);
      const glm::vec2 normal(std::sin(azimuth), -std::cos(azimuth));  // face A's normal (board_renderer)
      const glm::vec2 c = log.stem.pithAt(z) - d * normal;
      b.center = glm::vec3(c.x, c.y, z);
      boards.push_back(b);
      shades.push_back(std::clamp(1.0f + 0.12f * (unit(rng) - 0.5f), 0.9f, 1.1f));
    }
    panel.lamellas.push_back(std::move(boards));
    panel.shades.push_back(std::move(shades));
  }
  return panel;
}

PanelSample PlywoodPanel::map(const glm::vec3& p, float glueMm) const {
  const float t = plyThickness();
  const int ply = std::clamp(static_cast<int>(std::floor((p.z + 0.5f * size.z) / t)), 0, plies - 1);
  const float top = -0.5f * size.z + static_cast<float>(ply + 1) * t;
  const float depth = std::clamp(top - p.z, 0.0f, t);  // from the ply's face, the side the knife cut
  const bool alongLength = grainAlongLength(ply);
  const float across = alongLength ? p.x : p.y, along = alongLength ? p.y : p.x;
  const float extentAcross = alongLength ? size.x : size.y, extentAlong = alongLength ? size.y : size.x;
  const float u = plyStartU[ply] + across + 0.5f * extentAcross, v = along + 0.5f * extentAlong;
  PanelSample s{peel.toLog(u, v, depth * peel.thicknessMm / t), 1.0f};
  const bool belowInside = ply > 0, aboveInside = ply < plies - 1;
  if (glueMm > 0.0f && ((aboveInside && depth < glueMm) || (belowInside && t - depth < glueMm)))
    s.shade = glueShade;
  return s;
}

PlywoodPanel makePlywoodPanel(const LogModel& log, glm::vec3 size, int plies) {
  if (plies < 1 || !(size.x > 0 && size.y > 0 && size.z > 0))
    throw InputError("plywood: at least 1 ply and a positive panel size");
  checkPanelSize(size, "plywood");
  PlywoodPanel panel;
  panel.size = size;
  panel.plies = plies;
  const float extent = std::max(size.x, size.y);
  const float height = log.stem.height();
  const float z0 =
      std::clamp(knottiestHeight(log, extent) - 0.5f * extent, 0.0f, std::max(0.0f, height - extent));
  panel.peel = defaultPeel(log, panel.plyThickness(), z0);
  for (int i = 0; i < plies; ++i) panel.plyStartU.push_back(static_cast<float>(i) * (extent + 30.0f));
  const float needed = panel.plyStartU.back() + extent;
  if (needed > panel.peel.lengthToCore(0.3f * panel.peel.startRadiusMm)) {
    throw InputError("plywood: the log is too thin to peel " + std::to_string(plies) + " plies of " +
                     std::to_string(static_cast<int>(extent)) + " mm");
  }
  return panel;
}

Image renderCltFace(const KnotField& field, const WoodColorMap& colors, const CltPanel& panel, FaceId face,
                    int resolution, const Progress& progress) {
  return renderPanelFace(
      field, colors, panel.size, face, resolution,
      [&](const glm::vec3& p, float jointMm) { return panel.map(p, jointMm); }, progress);
}

Image renderPlywoodFace(const KnotField& field, const WoodColorMap& colors, const PlywoodPanel& panel,
                        FaceId face, int resolution, const Progress& progress) {
  return renderPanelFace(
      field, colors, panel.size, face, resolution,
      [&](const glm::vec3& p, float glueMm) { return panel.map(p, glueMm); }, progress);
}

Image renderVeneerSheet(const KnotField& field, const WoodColorMap& colors, const VeneerPeel& peel, float u0,
                        float lengthMm, float widthMm, int resolution, const Progress& progress) {
  if (resolution < 1 || !(lengthMm > 0.0f) || !(widthMm > 0.0f))
    throw InputError("veneer: a positive sheet size and at least 1 pixel");
  const float pxPerMm = static_cast<float>(resolution) / std::max(lengthMm, widthMm);
  const glm::ivec2 size(pixelsAlong(std::round(double(lengthMm) * pxPerMm)),
                        pixelsAlong(std::round(double(widthMm) * pxPerMm)));
  checkImageSize(size, "the image of the veneer sheet");
  const glm::vec2 mmPerPx(lengthMm / static_cast<float>(size.x), widthMm / static_cast<float>(size.y));
  return renderMapped(
      field, colors, size,
      [&](glm::vec2 pos) {
        return PanelSample{peel.toLog(u0 + pos.x * mmPerPx.x, pos.y * mmPerPx.y), 1.0f};
      },
      progress);
}

}  // namespace kerf
