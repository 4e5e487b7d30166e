#pragma once
// Wood products made of many pieces of one log, by mapping texture coordinates into the log (Larsson et al.
// 2022 Sec. 5; docs/knots.md, "CLT, veneer and plywood"):
//  - CLT (cross-laminated timber): layers of lamellas, each lamella a board cut from its own place in the
//    log, the layers' grain alternating between the panel's length and width;
//  - rotary-cut veneer: the sheet peeled off a log turning on a lathe; the knife follows an Archimedean
//    spiral, so sheet length u maps to radius r(u) = sqrt(r0^2 - t u / pi) (the arc length of
//    r = r0 - t theta / 2 pi from theta = 0, in closed form) and angle theta(u) = 2 pi (r0 - r(u)) / t;
//  - plywood: plies of veneer, grain alternating, each ply from its own stretch of the peel.
// Panels use the Kerf block frame (x width, y length, z thickness; faces A..F, docs/coordinates.md).
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "field/knot_field.hpp"
#include "geometry/block.hpp"
#include "image/image.hpp"
#include "render/board_renderer.hpp"
#include "util/progress.hpp"

namespace kerf {

// Where a panel point comes from in the log, and how much its colour is shaded (1: not at all).
struct PanelSample {
  glm::vec3 logPoint{0.0f};
  float shade = 1.0f;
};

// The spiral of a rotary lathe: a straight axis along the log (log z) at `axis`, the knife starting at
// radius r0 and moving in by the veneer thickness every turn.
struct VeneerPeel {
  glm::vec2 axis{0.0f};          // the lathe axis (log x, y)
  float startRadiusMm = 100.0f;  // r0
  float thicknessMm = 1.5f;      // t: the veneer thickness, the spiral's pitch per turn
  float startHeightMm = 0.0f;    // log z of the sheet's edge v = 0
  float startAzimuthRad = 0.0f;  // where the knife starts (theta = 0)

  float radiusAt(float u) const;                 // r(u), mm; 0 once the log is used up
  float angleAt(float u) const;                  // theta(u), radians turned
  float lengthToCore(float coreRadiusMm) const;  // u at which r(u) reaches the core radius
  // Sheet point (u along the peel, v across it up the log, depth into the sheet from its face) in the log.
  glm::vec3 toLog(float u, float v, float depthMm = 0.0f) const;
};

// A peel of the given log: the lathe axis on the pith of the log's middle, the knife starting just inside
// the bark (0.92 x the stem's smallest radius), the sheet's edge `startHeightMm` up the log.
VeneerPeel defaultPeel(const LogModel& log, float thicknessMm, float startHeightMm);

struct CltPanel {
  glm::vec3 size{600.0f, 600.0f, 90.0f};  // width, length (the outer layers' grain), thickness, mm
  int layers = 3;
  float lamellaWidthMm = 120.0f;
  std::vector<std::vector<Board>> lamellas;  // per layer (bottom, z = -size.z/2, first), per lamella
  std::vector<std::vector<float>> shades;    // per lamella: colour factor, the boards differ a little
  float jointShade = 0.45f;                  // the glue joints between lamellas and layers

  // The layer and lamella holding a panel point, and the point in that lamella's board frame.
  void locate(const glm::vec3& panelPoint, int& layer, int& lamella, glm::vec3& boardPoint) const;
  // The lamella's log point, shaded by its tint; `jointMm` > 0 darkens that far around the joints.
  PanelSample map(const glm::vec3& panelPoint, float jointMm = 0.0f) const;
  bool grainAlongLength(int layer) const { return layer % 2 == 0; }
  float layerThickness() const { return size.z / static_cast<float>(layers); }
};

// Lamellas cut from random places of the log (deterministic per seed): flat-sawn boards at a random
// height, direction and distance from the pith, each entirely inside the stem where the log allows.
CltPanel makeCltPanel(const LogModel& log, glm::vec3 sizeMm, int layers, float lamellaWidthMm,
                      std::uint32_t seed);

struct PlywoodPanel {
  glm::vec3 size{600.0f, 600.0f, 12.0f};
  int plies = 5;
  VeneerPeel peel;               // thickness = size.z / plies
  std::vector<float> plyStartU;  // per ply (bottom first): where on the peel its sheet starts, mm
  float glueShade = 0.55f;

  float plyThickness() const { return size.z / static_cast<float>(plies); }
  bool grainAlongLength(int ply) const { return ply % 2 == 0; }
  PanelSample map(const glm::vec3& panelPoint, float glueMm = 0.0f) const;
};

// Plies peeled one after the other from the same height of the log (the knottiest section).
PlywoodPanel makePlywoodPanel(const LogModel& log, glm::vec3 sizeMm, int plies);

// Face `face` of the panel, `resolution` pixels along its longer side (pixel centres as renderBoardFace),
// knots culled per 16 x 16 tile on the tile's own log points.
Image renderCltFace(const KnotField& field, const WoodColorMap& colors, const CltPanel& panel, FaceId face,
                    int resolution, const Progress& progress = {});
Image renderPlywoodFace(const KnotField& field, const WoodColorMap& colors, const PlywoodPanel& panel,
                        FaceId face, int resolution, const Progress& progress = {});
// A veneer sheet: image x = u in [u0, u0 + length], image y = v in [0, width] (down = up the log).
Image renderVeneerSheet(const KnotField& field, const WoodColorMap& colors, const VeneerPeel& peel, float u0,
                        float lengthMm, float widthMm, int resolution, const Progress& progress = {});

}  // namespace kerf
