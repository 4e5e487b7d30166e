// export: faces, cuts, volumes, depth stacks and textured parts in the format the output path's extension
// names (core/export/export_job.hpp, docs/export.md).
#include <cstdio>

#include "appearance/photo_true_source.hpp"
#include "command.hpp"
#include "export/export_job.hpp"
#include "io/project.hpp"
#include "number_option.hpp"
#include "util/error.hpp"
#include "util/number_list.hpp"

namespace kerf::cli {

Command addExportCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "export",
      "Export a face or cut image (" + extensionWords(ExportKind::Image) + "), a volume (" +
          extensionWords(ExportKind::Volume) + "), a depth stack (folder) or a textured part (" +
          extensionWords(ExportKind::Part) +
          " with --mesh), in the project's appearance (procedural or photo-true, colour volumes too)");
  struct Options {
    std::string document, out, face, plane, layer = "colour", exrType = "half", quantity = "growth",
                                            depthStack, mesh, place, rotate;
    float pxPerMm = 10.0f, scale = 1.0f;
    int samples = 2, resolution = 128, textureRes = 1024;
    bool noLayers = false, centre = false, requireFit = false;
  };
  auto o = std::make_shared<Options>();
  command->add_option("PROJECT", o->document, "A .kerf project or a Mokume-style sample folder")->required();
  command
      ->add_option("--out", o->out,
                   "Output: " + extensionWords(ExportKind::Image) + " (image), " +
                       extensionWords(ExportKind::Volume) + " (volume), a folder (--depth-stack), " +
                       extensionWords(ExportKind::Part) + " (part, --mesh)")
      ->required();
  command->add_option("--face", o->face, "Image of face A..F");
  command->add_option("--plane", o->plane,
                      "Image of the cut px,py,pz,nx,ny,nz (a point and a normal, block mm)");
  cli::addNumber(command, "--px-per-mm", o->pxPerMm,
                 "Image resolution; stored in the file as DPI and mm per pixel", 0.01f, 400.0f);
  cli::addNumber(command, "--samples", o->samples, "Supersamples per pixel side (parts: per texel side)", 1,
                 8);
  command->add_option("--layer", o->layer, "What a PNG holds: colour, growth (16-bit) or rings")
      ->check(CLI::IsMember({"colour", "color", "growth", "rings"}));
  command->add_flag("--no-layers", o->noLayers, "TIFF/EXR: colour only, without the growth and rings layers");
  command
      ->add_option("--exr-type", o->exrType, "EXR colour and rings channels: half or float (growth is float)")
      ->check(CLI::IsMember({"half", "float"}));
  command
      ->add_option("--quantity", o->quantity,
                   "Volume: growth (float years), color (RGB) or ring-uncertainty (float mm, from `fit "
                   "--uncertainty N`)")
      ->check(CLI::IsMember({"growth", "color", "colour", "ring-uncertainty"}));
  cli::addNumber(command, "--res", o->resolution, "Volume: samples along the block's longest side", 1, 4096);
  command->add_option(
      "--depth-stack", o->depthStack,
      "FACE,STEP_MM,DEPTH_MM: the face after removing 0, STEP, .. DEPTH mm, as numbered PNGs");
  command->add_option("--mesh", o->mesh, "Part: the mesh to bake (.obj, .stl, .ply; units read as mm)");
  command->add_option(
      "--place", o->place,
      "Part: tx,ty,tz mm, where the mesh origin goes in the block (with --centre: the part's centre)");
  command->add_option(
      "--rotate", o->rotate,
      "Part: rx,ry,rz degrees about the block's x, then y, then z axis (applied before --place)");
  cli::addPositive(command, "--scale", o->scale, "Part: uniform scale of the mesh (before turning)");
  command->add_flag(
      "--centre,--center", o->centre,
      "Part: centre the turned part's bounding box at --place (default 0,0,0: the block centre)");
  cli::addNumber(command, "--texture-res", o->textureRes, "Part: side of the square baked texture in px", 16,
                 16384);
  command->add_flag("--require-fit", o->requireFit,
                    "Part: fail when the part sticks out of the block (default: export and warn)");
  return {command, [o](Context& context) {
            ExportRequest request;
            request.out = o->out;
            if (!o->face.empty()) {
              const auto face = o->face.size() == 1 ? faceFromLetter(o->face[0]) : std::nullopt;
              if (!face) throw InputError("--face must be one of A, B, C, D, E, F (not \"" + o->face + "\")");
              request.face = face;
            }
            if (!o->plane.empty()) request.plane = parsePlane(o->plane);
            request.pxPerMm = o->pxPerMm;
            request.samples = o->samples;
            request.image.pngLayer = imageLayerFromName(o->layer);
            request.image.extraLayers = !o->noLayers;
            request.image.exrHalf = o->exrType == "half";
            request.quantity = volumeQuantityFromName(o->quantity);
            request.resolution = o->resolution;
            if (!o->depthStack.empty()) request.depthStack = parseDepthStack(o->depthStack);
            const auto vec3Option = [](const std::string& text, const std::string& option) {
              const std::vector<float> v = parseNumberList(text, option);
              if (v.size() != 3) throw InputError(option + " takes 3 numbers, not \"" + text + "\"");
              return glm::vec3(v[0], v[1], v[2]);
            };
            request.part.mesh = o->mesh;
            if (!o->place.empty()) request.part.placement.translationMm = vec3Option(o->place, "--place");
            if (!o->rotate.empty()) request.part.placement.rotationDeg = vec3Option(o->rotate, "--rotate");
            request.part.placement.scale = o->scale;
            request.part.placement.centreInBlock = o->centre;
            request.part.textureResolution = o->textureRes;
            request.part.requireFit = o->requireFit;
            exportKindOf(request);  // a bad path or option combination fails before the project is read
            const Project project = loadDocument(o->document);
            const WoodModel model(project);
            if (const RingUncertainty* sure = project.currentRingUncertainty())
              request.ringUncertainty = *sure;
            request.photoTrue = photoTrueSourceOf(project);
            const ExportSummary summary = runExport(model, request, context.progress());
            context.samples = summary.samples;
            std::printf("%s\n", summary.message.c_str());
            if (!summary.warning.empty())
              std::fprintf(stderr, "kerf-cli: warning: %s\n", summary.warning.c_str());
          }};
}

}  // namespace kerf::cli
