#pragma once
// The textured part export (issue 7): load a mesh, place it in the block, check that it fits, build a
// UV atlas, bake the block's wood onto it and write OBJ+MTL+PNG or binary glTF (format from the
// extension). The steps are in core/mesh/ and export/part_writers.hpp; docs/export.md describes them.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/mesh_topology.hpp"
#include "mesh/part_placement.hpp"
#include "util/progress.hpp"

namespace kerf {

class PhotoTrueAppearance;
class WoodModel;

struct PartExportOptions {
  std::filesystem::path mesh;  // .obj, .stl or .ply
  PartPlacement placement;
  int textureResolution = 1024;
  int samples = 2;  // per texel side (bake_part_texture.hpp)
  // A part that sticks out of the block is written anyway (the model continues the wood beyond the
  // block, which is fine for a preview) with a warning, unless this is set: then it is an InputError.
  bool requireFit = false;
};

struct PartExportResult {
  std::vector<std::filesystem::path> files;
  PartFit fit;
  MeshTopology topology;  // open edges are allowed (a surface can be baked) but worth a warning
  std::size_t triangles = 0, charts = 0, samples = 0;
  float texelsPerMm = 0;
  bool photoTrue = false;  // baked from the photo-true appearance
};

// out: .obj or .glb. Throws InputError (naming the mesh file), Cancelled. With `photoTrue` the texture is
// its appearance (export/photo_true_part_bake.hpp), else the procedural model's.
PartExportResult exportPart(const WoodModel& model, const PartExportOptions& options,
                            const std::filesystem::path& out, const Progress& progress = {},
                            const PhotoTrueAppearance* photoTrue = nullptr);

}  // namespace kerf
