// annotations: what ring traces and knot marks a sample folder or project holds, and their export in
// the Mokume annotation format (<F>_ann.png numbered rings, <F>_knot.png knot marks; docs/rings.md).
#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "io/image.hpp"
#include "io/mokume_annotation_files.hpp"
#include "io/project.hpp"
#include "number_option.hpp"
#include "rings/annotations.hpp"
#include "util/error.hpp"

namespace fs = std::filesystem;

namespace kerf::cli {

Command addAnnotationsCommand(CLI::App& app) {
  auto* command =
      app.add_subcommand("annotations",
                         "List the ring traces and knot marks of a sample folder or project; export them as "
                         "Mokume annotation images (X_ann.png, X_knot.png)");
  struct Options {
    std::string document, exportDir;
    float pxPerMm = 0;
  };
  auto o = std::make_shared<Options>();
  command->add_option("DOCUMENT", o->document, "A .kerf project or a sample folder")->required();
  command->add_option("--export-mokume", o->exportDir,
                      "Write <face>_ann.png (pixel = year, 255 = background) for faces with numbered traces "
                      "and <face>_knot.png (grey 200 = knot centre) for faces with knot marks into DIR");
  cli::addPositive(command, "--px-per-mm", o->pxPerMm,
                   "Resolution of the exported images (default: the face photo's size, else 6.4 px/mm, "
                   "Mokume's 256 px on 40 mm)");
  return {command, [o](Context&) {
            const Project project = loadDocument(o->document);
            const Annotations& a = project.annotations;
            std::string perFace;
            int numbered = 0;
            for (FaceId face : kAllFaces) {
              int traces = 0, knots = 0;
              for (const RingTrace& t : a.traces)
                traces += t.face == face, numbered += t.face == face && t.year;
              for (const KnotMark& k : a.knots) knots += k.face == face;
              perFace += std::string(" ") + faceLetter(face) + ":" + std::to_string(traces) +
                         (knots ? "+" + std::to_string(knots) + "k" : "");
            }
            std::printf(
                "%zu ring traces (%d numbered), %zu knot marks of %d knots; per face (traces+knots):%s\n",
                a.traces.size(), numbered, a.knots.size(), a.nextKnotId(), perFace.c_str());
            if (o->exportDir.empty()) return;
            if (numbered == 0 && a.knots.empty())
              throw InputError(o->document +
                               " has no numbered ring traces and no knot marks: there is nothing to write in "
                               "the Mokume annotation format (number the traces by year in the editor)");
            std::array<glm::ivec2, 6> sizes;
            for (FaceId face : kAllFaces) {
              const fs::path& photo = project.facePhotos[faceIndex(face)];
              sizes[faceIndex(face)] = o->pxPerMm > 0   ? project.block.faceImageSize(face, o->pxPerMm)
                                       : !photo.empty() ? readImageSize(photo)
                                                        : mokumeImageSize(project.block, face);
            }
            const auto written = writeMokumeAnnotations(a, project.block, o->exportDir, sizes);
            std::string names;
            for (const fs::path& file : written) names += " " + file.filename().string();
            std::printf("Mokume annotations written to %s:%s\n", o->exportDir.c_str(), names.c_str());
            if (numbered < static_cast<int>(a.traces.size()))
              std::fprintf(stderr, "kerf-cli: note: %zu unnumbered traces are not in the Mokume images\n",
                           a.traces.size() - numbered);
          }};
}

}  // namespace kerf::cli
