// render-panel: CLT, rotary-cut veneer and plywood from a log (Larsson et al. 2022 Sec. 5; docs/knots.md).
#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "field/knot_field.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "log_arguments.hpp"
#include "number_option.hpp"
#include "render/panel_render.hpp"
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
  cli::addNumber(cmd, "--res", o->resolution, "Pixels along the image's longer side", 1, 16384);
  cmd->add_option("--face", o->face, "clt, plywood: which face of the panel, A..F (A: the top)")
      ->check(CLI::IsMember({"A", "B", "C", "D", "E", "F", "a", "b", "c", "d", "e", "f"}));
  cmd->add_option("--size", o->size,
                  "clt, plywood: width,length,thickness in mm (default 600,600,90 for clt, 600,600,12 for "
                  "plywood)");
  cli::addNumber(cmd, "--layers", o->layers, "clt: layers (default 3); plywood: plies (default 5)", 1, 64);
  cli::addPositive(cmd, "--lamella-width", o->lamellaWidth, "clt: width of the lamellas (boards), mm");
  cli::addNumber(cmd, "--seed", o->seed,
                 "clt: where in the log the lamellas are cut (each seed another panel)");
  cli::addPositive(cmd, "--thickness", o->thickness,
                   "veneer: the sheet's thickness (the knife's pitch per turn), mm");
  cmd->add_option("--sheet", o->sheet, "veneer: length (along the peel),width (up the log) in mm");
  cli::addNumber(cmd, "--start", o->start,
                 "veneer: where on the peel the sheet starts, mm from the first cut", 0);
  cli::addNumber(cmd, "--height", o->height,
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
            PanelOptions options;
            options.type = o->type == "clt"       ? PanelType::Clt
                           : o->type == "plywood" ? PanelType::Plywood
                                                  : PanelType::Veneer;
            options.resolution = o->resolution;
            options.face = *faceFromLetter(o->face[0]);
            if (!o->size.empty()) {
              const std::vector<float> v = parseNumberList(o->size, "--size");
              if (v.size() != 3)
                throw InputError("--size takes width,length,thickness in mm (3 positive numbers)");
              options.sizeMm = glm::vec3(v[0], v[1], v[2]);
            }
            options.layers = o->layers;
            options.lamellaWidthMm = o->lamellaWidth;
            options.seed = o->seed;
            options.veneerThicknessMm = o->thickness;
            if (options.type == PanelType::Veneer) {
              const std::vector<float> sheet = parseNumberList(o->sheet, "--sheet");
              if (sheet.size() != 2)
                throw InputError("--sheet takes length,width in mm (2 positive numbers)");
              options.sheetMm = glm::vec2(sheet[0], sheet[1]);
            }
            options.startMm = o->start;
            options.heightMm = o->height;
            const RenderedPanel panel = renderPanel(field, colors, options, context.progress());
            const Image& image = panel.image;
            const std::string& what = panel.description;
            const std::filesystem::path parent = std::filesystem::path(o->out).parent_path();
            if (!parent.empty()) createOutputFolder(parent);
            writeImage(o->out, image);
            context.samples = static_cast<std::size_t>(image.width) * image.height;
            std::printf("%s written to %s (%d x %d px)\n", what.c_str(), o->out.c_str(), image.width,
                        image.height);
          }};
}

}  // namespace kerf::cli
