#pragma once
// One picture of a CLT panel, a rotary-cut veneer sheet or plywood made from a log
// (render/layered_panels.hpp, docs/knots.md "CLT, veneer and plywood"), with the defaults and checks of
// `kerf-cli render-panel`; the editor's Panel view shows the same.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "field/knot_field.hpp"
#include "geometry/block.hpp"
#include "image/image.hpp"
#include "util/progress.hpp"

namespace kerf {

enum class PanelType { Clt, Veneer, Plywood };

struct PanelOptions {
  PanelType type = PanelType::Clt;
  int resolution = 1200;    // pixels along the image's longer side
  FaceId face = FaceId::A;  // clt, plywood
  glm::vec3 sizeMm{0.0f};   // clt, plywood: width, length, thickness; 0: 600 x 600 x 90 (clt), x 12 (plywood)
  int layers = 0;           // clt: layers (0: 3); plywood: plies (0: 5)
  float lamellaWidthMm = 120.0f;       // clt
  std::uint32_t seed = 1;              // clt: where the lamellas are cut
  float veneerThicknessMm = 1.5f;      // veneer: the knife's pitch per turn
  glm::vec2 sheetMm{1200.0f, 600.0f};  // veneer: length along the peel, width up the log
  float startMm = 0.0f;                // veneer: where on the peel the sheet starts
  float heightMm = -1.0f;              // veneer: log height of its lower edge (< 0: the knottiest section)
};

struct RenderedPanel {
  Image image;              // RGB
  std::string description;  // e.g. "CLT panel, 3 layers, face A"
};

// Throws InputError for a size that is not positive or a veneer sheet that runs past the log's centre.
RenderedPanel renderPanel(const KnotField& field, const WoodColorMap& colors, const PanelOptions& options,
                          const Progress& progress = {});

}  // namespace kerf
