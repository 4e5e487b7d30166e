// render-panel: CLT, rotary-cut veneer and plywood from a log (Larsson et al. 2022 Sec. 5; docs/knots.md).
#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "field/knot_field.hpp"
#include "log_arguments.hpp"
#include "render/layered_panels.hpp"
#include "util/error.hpp"
#include "util/number_list.hpp"

namespace kerf::cli {

Command addRenderPanelCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "render-panel",
      "Render a CLT panel, a rotary-cut veneer sheet or plywood made from a log (docs/knots.md)");
  struct Options {
    std::string log, out, type, face = "A", size, sheet = "1200,600";
    std::vector<std::string> settings;
    int resolution = 1200, layers = 0;
    unsigned seed = 1;
    float lamellaWidth = 120.0f, thickness = 1.5f, start = 0.0f, height = -1.0f;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("LOG", o->log, "A Kerf log file (.kerflog), a Gran_1 folder, or random:SEED")->required();
  cmd->add_option("--type", o->type, "clt, veneer or plywood")
      ->required()
      ->check(CLI::IsMember({"clt", "veneer", "plywood"}));
  cmd->add_option("--out", o->out, "Output image (PNG, ...)")->required();
  cmd->add_option("--res", o->resolution, "Pixels along the image's longer side")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--face", o->face, "clt, plywood: which face of the panel, A..F (A: the top)")
      ->check(CLI::IsMember({"A", "B", "C", "D", "E", "F", "a", "b", "c", "d", "e", "f"}));
  cmd->add_option("--size", o->size,
                  "clt, plywood: width,length,thickness in mm (default 600,600,90 for clt, 600,600,12 for "
                  "plywood)");
  cmd->add_option("--layers", o->layers, "clt: layers (default 3); plywood: plies (default 5)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--lamella-width", o->lamellaWidth, "clt: width of the lamellas (boards), mm")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", o->seed, "clt: where in the log the lamellas are cut (each seed another panel)");
  cmd->add_option("--thickness", o->thickness,
                  "veneer: the sheet's thickness (the knife's pitch per turn), mm")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--sheet", o->sheet, "veneer: length (along the peel),width (up the log) in mm");
  cmd->add_option("--start", o->start, "veneer: where on the peel the sheet starts, mm from the first cut")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--height", o->height,
                  "veneer: log height of the sheet's lower edge, mm (default: the knottiest section)");
  cmd->add_option("--set", o->settings, "Override a parameter: id=value (e.g. knots.butterfly=0.8)");
  return {cmd, [o](Context& context) {
            const LogModel log = loadLogArgument(o->log);
            WoodParameters params;
            for (const std::string& s : o->settings) applySetting(params, s);
            const WoodColorMap colors = log.colorMap.empty()
                                            ? woodColorMapFromParameters(params, log.stem.maxRadius())
                                            : log.colorMap;
            const KnotField field(log, KnotSettings::fromParameters(params));
            const FaceId face = *faceFromLetter(o->face[0]);
            const auto panelSize = [&](glm::vec3 fallback) {
              if (o->size.empty()) return fallback;
              const std::vector<float> v = parseNumberList(o->size, "--size");
              if (v.size() != 3 || !(v[0] > 0 && v[1] > 0 && v[2] > 0))
                throw InputError("--size takes width,length,thickness in mm (3 positive numbers)");
              return glm::vec3(v[0], v[1], v[2]);
            };
            Image image;
            std::string what;
            if (o->type == "clt") {
              const CltPanel panel = makeCltPanel(log, panelSize({600.0f, 600.0f, 90.0f}),
                                                  o->layers > 0 ? o->layers : 3, o->lamellaWidth, o->seed);
              image = renderCltFace(field, colors, panel, face, o->resolution, context.progress());
              what = "CLT panel, " + std::to_string(panel.layers) + " layers, face " + o->face;
            } else if (o->type == "plywood") {
              const PlywoodPanel panel =
                  makePlywoodPanel(log, panelSize({600.0f, 600.0f, 12.0f}), o->layers > 0 ? o->layers : 5);
              image = renderPlywoodFace(field, colors, panel, face, o->resolution, context.progress());
              what = "plywood, " + std::to_string(panel.plies) + " plies, face " + o->face;
            } else {
              const std::vector<float> sheet = parseNumberList(o->sheet, "--sheet");
              if (sheet.size() != 2 || !(sheet[0] > 0 && sheet[1] > 0))
                throw InputError("--sheet takes length,width in mm (2 positive numbers)");
              const float height = o->height >= 0.0f
                                       ? o->height
                                       : std::max(0.0f, knottiestHeight(log, sheet[1]) - 0.5f * sheet[1]);
              const VeneerPeel peel = defaultPeel(log, o->thickness, height);
              if (o->start + sheet[0] > peel.lengthToCore(0.0f))
                throw InputError("--start + sheet length run past the log's centre");
              image = renderVeneerSheet(field, colors, peel, o->start, sheet[0], sheet[1], o->resolution,
                                        context.progress());
              what = "rotary-cut veneer, r " + std::to_string(peel.radiusAt(o->start)) + " to " +
                     std::to_string(peel.radiusAt(o->start + sheet[0])) + " mm";
            }
            const std::filesystem::path parent = std::filesystem::path(o->out).parent_path();
            if (!parent.empty()) std::filesystem::create_directories(parent);
            writeImage(o->out, image);
            context.samples = static_cast<std::size_t>(image.width) * image.height;
            std::printf("%s written to %s (%d x %d px)\n", what.c_str(), o->out.c_str(), image.width,
                        image.height);
          }};
}

}  // namespace kerf::cli
