// export-volume: the growth field or the colour as a NRRD or OpenVDB volume (also `export` with .nrrd/.vdb).
#include <cstdio>

#include "appearance/photo_true_source.hpp"
#include "command.hpp"
#include "export/export_formats.hpp"
#include "export/volume_export.hpp"
#include "io/project.hpp"
#include "number_option.hpp"

namespace kerf::cli {

Command addExportVolumeCommand(CLI::App& app) {
  auto* volume = app.add_subcommand(
      "export-volume",
      "Write the growth field, the colour or the fit's ring uncertainty as a NRRD or OpenVDB volume "
      "(by extension)");
  struct Options {
    std::string document, quantity = "growth", out;
    int resolution = 128;
  };
  auto o = std::make_shared<Options>();
  volume->add_option("PROJECT", o->document, "A .kerf project or a Mokume-style sample folder")->required();
  volume
      ->add_option("--quantity", o->quantity,
                   "growth (float years), color (uint8 RGB, in the project's appearance: photo-true or "
                   "procedural) or ring-uncertainty "
                   "(float mm: how sure the fit "
                   "is, 1 sigma; from `fit --uncertainty N`)")
      ->check(CLI::IsMember({"growth", "color", "ring-uncertainty"}));
  cli::addNumber(volume, "--res", o->resolution, "Samples along the block's longest side", 1, 4096);
  volume->add_option("--out", o->out, "Output " + extensionList(ExportKind::Volume) + " file")->required();
  return {volume, [o](Context& context) {
            const Project project = loadDocument(o->document);
            const WoodModel model(project);
            const VolumeQuantity quantity = volumeQuantityFromName(o->quantity);
            // A colour volume of a photo-true project is made of its photos (issue 17).
            const std::optional<PhotoTrueSource> source = photoTrueSourceOf(project);
            const Progress progress = context.progress();
            std::unique_ptr<PhotoTrueAppearance> photoTrue;
            if (source && quantity == VolumeQuantity::Color)
              photoTrue = makePhotoTrueAppearance(model, *source, progress.part(0.0, 0.05));
            const VolumeExportResult result = exportVolume(model, quantity, o->resolution, o->out,
                                                           photoTrue ? progress.part(0.05, 1.0) : progress,
                                                           project.currentRingUncertainty(), photoTrue.get());
            context.samples = result.samples;
            std::printf("volume written to %s%s (%d x %d x %d samples, %.4g mm spacing, %.1f MiB)\n",
                        o->out.c_str(), photoTrue ? " in the photo-true appearance" : "", result.size.x,
                        result.size.y, result.size.z, result.spacingMm.x, result.bytes / 1048576.0);
          }};
}

}  // namespace kerf::cli
