// render-faces and render-cut: images of the model.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <vector>

#include "appearance/project_render.hpp"
#include "command.hpp"
#include "geometry/cut_plane.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "number_option.hpp"
#include "render/renderers.hpp"
#include "render/unfolded_cross.hpp"
#include "util/error.hpp"
#include "util/number_list.hpp"

namespace fs = std::filesystem;

namespace kerf::cli {

CutPlane parsePlane(const std::string& text) {
  const std::vector<float> v = parseNumberList(text, "--plane");
  if (v.size() != 6)
    throw InputError("--plane takes 6 numbers: px,py,pz,nx,ny,nz (a point and a normal, block mm)");
  return CutPlane({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
}

Command addRenderFacesCommand(CLI::App& app) {
  auto* faces = app.add_subcommand(
      "render-faces",
      "Render the model's six faces A.png..F.png (in the project's appearance: procedural or photo-true)");
  struct Options {
    std::string document, out;
    float pxPerMm = 6.4f;
    int samples = 2;
    bool cross = false;
  };
  auto o = std::make_shared<Options>();
  faces->add_option("PROJECT", o->document, "A .kerf project or a Mokume-style sample folder")->required();
  faces->add_option("--out", o->out, "Output folder (created if needed)")->required();
  cli::addNumber(faces, "--px-per-mm", o->pxPerMm, "Resolution (6.4 = Mokume's 256 px per 40 mm)", 0.01f,
                 400.0f);
  cli::addNumber(faces, "--samples", o->samples, "Supersamples per pixel side", 1, 8);
  faces->add_flag("--unfolded", o->cross, "Also write unfolded.png: the faces in the Mokume cross layout");
  return {
      faces, [o](Context& context) {
        const Project project = loadDocument(o->document);
        const WoodModel model(project);
        createOutputFolder(o->out);
        const auto images = renderProjectFaces(project, model, o->pxPerMm, o->samples, context.progress());
        for (FaceId face : kAllFaces) {
          const Image& image = images[faceIndex(face)];
          writeImage(fs::path(o->out) / (std::string(1, faceLetter(face)) + ".png"), image);
          context.samples += static_cast<std::size_t>(image.width) * image.height * o->samples * o->samples;
        }
        if (o->cross) writeImage(fs::path(o->out) / "unfolded.png", unfoldedCross(images, model.block()));
        std::printf("faces written to %s (A.png .. F.png%s)\n", o->out.c_str(),
                    o->cross ? ", unfolded.png" : "");
      }};
}

Command addRenderCutCommand(CLI::App& app) {
  auto* cut = app.add_subcommand(
      "render-cut",
      "Render the cut surface of a plane through the block (RGBA PNG; in the project's appearance)");
  struct Options {
    std::string document, plane, out;
    float pxPerMm = 10.0f;
    int samples = 2;
  };
  auto o = std::make_shared<Options>();
  cut->add_option("PROJECT", o->document, "A .kerf project or a Mokume-style sample folder")->required();
  cut->add_option("--plane", o->plane, "px,py,pz,nx,ny,nz: a point on the plane and its normal, block mm")
      ->required();
  cli::addNumber(cut, "--px-per-mm", o->pxPerMm, "Resolution of the cut image", 0.01f, 400.0f);
  cli::addNumber(cut, "--samples", o->samples, "Supersamples per pixel side", 1, 8);
  cut->add_option("--out", o->out, "Output image (.png, .tif, ...)")->required();
  return {cut, [o](Context& context) {
            const CutPlane plane = parsePlane(o->plane);
            const Project project = loadDocument(o->document);
            const WoodModel model(project);
            const Image image =
                renderProjectCut(project, model, plane, o->pxPerMm, o->samples, context.progress());
            writeImage(o->out, image);
            context.samples = static_cast<std::size_t>(image.width) * image.height * o->samples * o->samples;
            std::printf("cut written to %s (%dx%d px, %.3g px/mm)\n", o->out.c_str(), image.width,
                        image.height, o->pxPerMm);
          }};
}

}  // namespace kerf::cli
