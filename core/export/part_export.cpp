#include "export/part_export.hpp"

#include "export/export_formats.hpp"
#include "export/part_writers.hpp"
#include "export/photo_true_part_bake.hpp"
#include "mesh/bake_part_texture.hpp"
#include "mesh/mesh_loader.hpp"
#include "mesh/uv_atlas.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"

namespace kerf {

PartExportResult exportPart(const WoodModel& model, const PartExportOptions& options,
                            const std::filesystem::path& out, const Progress& progress,
                            const PhotoTrueAppearance* photoTrue) {
  const ExportFormatInfo format = requireExportFormat(out, ExportKind::Part, "a textured part");
  if (options.mesh.empty())
    throw InputError("a part export (" + std::string(format.extensions[0]) +
                     ") needs a mesh: --mesh FILE (.obj, .stl or .ply)");
  if (options.textureResolution < 16 || options.textureResolution > 16384)
    throw InputError("the texture resolution must be between 16 and 16384 texels, not " +
                     std::to_string(options.textureResolution));
  validatePlacement(options.placement);
  const std::filesystem::path folder = out.parent_path().empty() ? "." : out.parent_path();
  if (!std::filesystem::is_directory(folder))
    throw InputError("cannot write " + out.string() + ": folder " + folder.string() + " does not exist");

  const Mesh mesh = loadMesh(options.mesh);
  const Mesh placed = placeMesh(mesh, options.placement);
  PartExportResult result;
  result.fit = checkPartFit(model.block(), placed.positions);
  result.topology = meshTopology(mesh);
  if (options.requireFit && !result.fit.fits())
    throw InputError("part " + options.mesh.string() + ": " + result.fit.describe());
  progress.throwIfCancelled();

  UvAtlasOptions atlasOptions;
  atlasOptions.resolution = options.textureResolution;
  const UvAtlas atlas = buildUvAtlas(placed, atlasOptions);
  progress.set(0.05);
  const BakedTexture baked =
      photoTrue
          ? bakePhotoTruePart(*photoTrue, model, placed, atlas, options.samples, progress.part(0.05, 0.9))
          : bakePartTexture(model, atlas, options.samples, progress.part(0.05, 0.9));
  if (format.format == ExportFormat::Obj) {
    result.files = writePartObj(out, atlas.mesh, baked.image);
  } else {
    writePartGlb(out, atlas.mesh, baked.image);
    result.files = {out};
  }
  progress.set(1.0);
  result.triangles = atlas.mesh.triangles.size();
  result.charts = atlas.charts.size();
  result.samples = baked.samples;
  result.texelsPerMm = atlas.texelsPerMm;
  result.photoTrue = photoTrue != nullptr;
  return result;
}

}  // namespace kerf
