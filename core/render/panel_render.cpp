#include "render/panel_render.hpp"

#include <algorithm>
#include <cstdio>

#include "render/layered_panels.hpp"
#include "util/error.hpp"

namespace kerf {

RenderedPanel renderPanel(const KnotField& field, const WoodColorMap& colors, const PanelOptions& o,
                          const Progress& progress) {
  const LogModel& log = field.log();
  const auto panelSize = [&](glm::vec3 fallback) {
    if (o.sizeMm == glm::vec3(0.0f)) return fallback;
    if (!(o.sizeMm.x > 0 && o.sizeMm.y > 0 && o.sizeMm.z > 0))
      throw InputError("the panel size takes width, length and thickness in mm (3 positive numbers)");
    return o.sizeMm;
  };
  const std::string face(1, faceLetter(o.face));
  RenderedPanel out;
  if (o.type == PanelType::Clt) {
    const CltPanel panel = makeCltPanel(log, panelSize({600.0f, 600.0f, 90.0f}), o.layers > 0 ? o.layers : 3,
                                        o.lamellaWidthMm, o.seed);
    out.image = renderCltFace(field, colors, panel, o.face, o.resolution, progress);
    out.description = "CLT panel, " + std::to_string(panel.layers) + " layers, face " + face;
  } else if (o.type == PanelType::Plywood) {
    const PlywoodPanel panel =
        makePlywoodPanel(log, panelSize({600.0f, 600.0f, 12.0f}), o.layers > 0 ? o.layers : 5);
    out.image = renderPlywoodFace(field, colors, panel, o.face, o.resolution, progress);
    out.description = "plywood, " + std::to_string(panel.plies) + " plies, face " + face;
  } else {
    if (!(o.sheetMm.x > 0 && o.sheetMm.y > 0))
      throw InputError("the veneer sheet takes a length and a width in mm (2 positive numbers)");
    const float height = o.heightMm >= 0.0f
                             ? o.heightMm
                             : std::max(0.0f, knottiestHeight(log, o.sheetMm.y) - 0.5f * o.sheetMm.y);
    const VeneerPeel peel = defaultPeel(log, o.veneerThicknessMm, height);
    const float available = peel.lengthToCore(0.0f);
    if (o.startMm + o.sheetMm.x > available) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "the veneer sheet's start + length (%.0f mm) run past the log's centre (%.0f mm of peel)",
                    o.startMm + o.sheetMm.x, available);
      throw InputError(text);
    }
    out.image =
        renderVeneerSheet(field, colors, peel, o.startMm, o.sheetMm.x, o.sheetMm.y, o.resolution, progress);
    char text[160];
    std::snprintf(text, sizeof text, "rotary-cut veneer, r %.1f to %.1f mm", peel.radiusAt(o.startMm),
                  peel.radiusAt(o.startMm + o.sheetMm.x));
    out.description = text;
  }
  return out;
}

}  // namespace kerf
