#include "export/export_job.hpp"

#include <sstream>

#include "util/error.hpp"
#include "util/file_extension.hpp"

namespace kerf {
namespace {

std::string sizeText(int width, int height, float pxPerMm) {
  std::ostringstream s;
  s.precision(4);
  s << width << " x " << height << " px, " << pxPerMm << " px/mm = " << pxPerMm * 25.4f << " dpi";
  return s.str();
}

// " (photo-true)" after what was written, when it shows the photo-true appearance.
std::string appearanceNote(const PhotoTrueAppearance* photoTrue) {
  return photoTrue ? " in the photo-true appearance" : "";
}

// Whether the export writes colours (the photo-true appearance is made only then: it takes seconds).
bool writesColour(const ExportRequest& request, ExportKind kind) {
  switch (kind) {
    case ExportKind::Image:
      return exportFormatOf(request.out)->format != ExportFormat::Png ||
             request.image.pngLayer == ImageLayer::Colour;
    case ExportKind::DepthStack:
      return request.image.pngLayer == ImageLayer::Colour;
    case ExportKind::Part:
      return true;
    case ExportKind::Volume:
      return request.quantity == VolumeQuantity::Color;
  }
  return false;
}

ExportSummary runPartExport(const WoodModel& model, const ExportRequest& request, const Progress& progress,
                            const PhotoTrueAppearance* photoTrue) {
  PartExportOptions options = request.part;
  options.samples = request.samples;  // --samples, as for images
  const PartExportResult result = exportPart(model, options, request.out, progress, photoTrue);
  ExportSummary summary;
  summary.kind = ExportKind::Part;
  summary.samples = result.samples;
  std::ostringstream s;
  s.precision(4);
  s << "part written to " << request.out.string() << appearanceNote(photoTrue) << " (" << result.triangles
    << " triangles in " << result.charts << " charts, " << request.part.textureResolution << " px texture, "
    << result.texelsPerMm << " texels/mm";
  if (result.files.size() > 1)
    s << "; with " << result.files[1].filename().string() << " and " << result.files[2].filename().string();
  s << "); " << result.fit.describe();
  summary.message = s.str();
  if (!result.fit.fits())
    summary.warning = result.fit.describe() + "; the wood there is the model continued beyond the block";
  if (!result.topology.closed()) {
    if (!summary.warning.empty()) summary.warning += "; ";
    summary.warning += "the mesh is not a closed solid: " + result.topology.describeOpen();
  }
  return summary;
}

}  // namespace

ExportKind exportKindOf(const ExportRequest& request) {
  if (request.out.empty()) throw InputError("no output path given");
  const std::optional<ExportFormatInfo> format = exportFormatOf(request.out);
  if (request.depthStack) {
    if (format)
      throw InputError("a depth stack is written into a folder, not a " + lowerExtension(request.out) +
                       " file: " + request.out.string());
    return ExportKind::DepthStack;
  }
  if (!format)
    throw InputError("cannot tell what to export from \"" + request.out.string() + "\": use " +
                     extensionList(ExportKind::Image) + " for an image, " +
                     extensionList(ExportKind::Volume) + " for a volume, " + extensionList(ExportKind::Part) +
                     " for a textured part (with --mesh), or a folder with --depth-stack");
  if (format->kind == ExportKind::Image) {
    if (request.face.has_value() == request.plane.has_value())
      throw InputError("an image export needs either a face (--face A..F) or a cut plane (--plane), not " +
                       std::string(request.face ? "both" : "neither"));
    return ExportKind::Image;
  }
  return format->kind;
}

ExportSummary runExport(const WoodModel& model, const ExportRequest& request, const Progress& wholeProgress) {
  ExportSummary summary;
  summary.kind = exportKindOf(request);
  const std::string out = request.out.string();
  std::unique_ptr<PhotoTrueAppearance> appearance;
  if (request.photoTrue && writesColour(request, summary.kind))
    appearance = makePhotoTrueAppearance(model, *request.photoTrue, wholeProgress.part(0.0, 0.05));
  const PhotoTrueAppearance* photoTrue = appearance.get();
  const Progress progress = photoTrue ? wholeProgress.part(0.05, 1.0) : wholeProgress;
  switch (summary.kind) {
    case ExportKind::Image: {
      const LayeredImage image = request.face
                                     ? renderFaceLayers(model, *request.face, request.pxPerMm,
                                                        request.samples, progress.part(0, 0.95), photoTrue)
                                     : renderCutLayers(model, *request.plane, request.pxPerMm,
                                                       request.samples, progress.part(0, 0.95), photoTrue);
      writeLayeredImage(request.out, image, request.image);
      progress.set(1.0);
      const std::size_t pixels = static_cast<std::size_t>(image.colour.width) * image.colour.height;
      // Model evaluations: the colour's supersamples (none for the photo-true colour) and the growth.
      summary.samples = pixels * ((photoTrue ? 0 : request.samples * request.samples) + 1);
      summary.message =
          std::string(request.face ? "face " + std::string(1, faceLetter(*request.face)) : "cut") +
          " written to " + out + appearanceNote(photoTrue) + " (" +
          sizeText(image.colour.width, image.colour.height, request.pxPerMm) + ")";
      return summary;
    }
    case ExportKind::Volume: {
      const VolumeExportResult result =
          exportVolume(model, request.quantity, request.resolution, request.out, progress,
                       request.ringUncertainty ? &*request.ringUncertainty : nullptr, photoTrue);
      summary.samples = result.samples;
      std::ostringstream s;
      s.precision(4);
      s << "volume written to " << out << appearanceNote(photoTrue) << " (" << result.size.x << " x "
        << result.size.y << " x " << result.size.z << " samples, " << result.spacingMm.x << " mm spacing, "
        << result.bytes / 1048576.0 << " MiB)";
      summary.message = s.str();
      return summary;
    }
    case ExportKind::DepthStack: {
      DepthStackOptions options = *request.depthStack;
      options.pxPerMm = request.pxPerMm;
      options.samples = request.samples;
      options.layer = request.image.pngLayer;
      const DepthStackResult result = exportDepthStack(model, options, request.out, progress, photoTrue);
      const glm::ivec2 size = model.block().faceImageSize(options.face, options.pxPerMm);
      summary.samples = result.files.size() * static_cast<std::size_t>(size.x) * size.y *
                        (options.samples * options.samples + 1);
      std::ostringstream s;
      s.precision(4);
      s << "depth stack written to " << out << appearanceNote(photoTrue) << " (" << result.files.size()
        << " images of face " << faceLetter(options.face) << ", 0 to " << result.depthsMm.back() << " mm, "
        << sizeText(size.x, size.y, options.pxPerMm) << "; index depths.csv)";
      summary.message = s.str();
      return summary;
    }
    case ExportKind::Part:
      return runPartExport(model, request, progress, photoTrue);
  }
  return summary;
}

}  // namespace kerf
