#pragma once
// One export, as `kerf-cli export` and the editor's File > Export dialogs describe it: what to write is
// picked from the output path's extension (the formats: export/export_formats.hpp; docs/export.md):
//   an image format        a face (face) or a cut (plane) image with layers (export/image_export.hpp)
//   a volume format        a volume of the growth field or the colour (export/volume_export.hpp)
//   a folder               a depth stack (depthStack set; export/depth_stack.hpp)
//   a part format          a textured part: a placed mesh baked with the wood (export/part_export.hpp)
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "appearance/photo_true_source.hpp"
#include "export/depth_stack.hpp"
#include "export/export_formats.hpp"
#include "export/image_export.hpp"
#include "export/part_export.hpp"
#include "export/volume_export.hpp"

namespace kerf {

struct ExportRequest {
  std::filesystem::path out;
  // Images: exactly one of face and plane.
  std::optional<FaceId> face;
  std::optional<CutPlane> plane;
  float pxPerMm = 10.0f;
  int samples = 2;
  ImageWriteOptions image;
  // Volumes.
  VolumeQuantity quantity = VolumeQuantity::Growth;
  int resolution = 128;
  // The project's ring uncertainty of the model's field (Project::currentRingUncertainty), for
  // VolumeQuantity::RingUncertainty; none: that quantity is refused.
  std::optional<RingUncertainty> ringUncertainty;
  // Depth stacks (face, step, depth; pxPerMm, samples and image.pngLayer come from the fields above).
  std::optional<DepthStackOptions> depthStack;
  // Parts (.obj, .glb): the mesh, its placement and the texture resolution (supersampling: `samples`).
  PartExportOptions part;
  // The project's photo-true appearance (photoTrueSourceOf(project); issue 17), none when procedural.
  // Images, depth stacks and parts then show its colours (the photos are read when the export runs);
  // a colour volume stays the procedural model's, with a warning (docs/export.md).
  std::optional<PhotoTrueSource> photoTrue;
};

// The kind `request` asks for. Throws InputError for an unknown extension, an image without a face or
// plane (or with both), or a depth stack whose path has an image or volume extension.
ExportKind exportKindOf(const ExportRequest& request);

struct ExportSummary {
  ExportKind kind = ExportKind::Image;
  std::string message;      // one line for the user: what was written where
  std::size_t samples = 0;  // model evaluations, for --stats
  std::string warning;      // something the user should know although the export succeeded (empty: none)
};

// Checks the request, renders and writes, atomically (a depth stack: each file). Throws InputError
// (with a message for the user), Cancelled.
ExportSummary runExport(const WoodModel& model, const ExportRequest& request, const Progress& progress = {});

}  // namespace kerf
