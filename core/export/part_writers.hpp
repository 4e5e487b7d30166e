#pragma once
// Writing a baked part (issue 7). Both formats hold the part where it sits in the block (block frame,
// docs/coordinates.md), with the atlas's normals and texture coordinates, and the baked texture.
//
// OBJ: `part.obj` (positions in mm, `vt` with v up as OBJ readers expect, i.e. 1 - v of the atlas),
// `part.mtl` (material `wood`, map_Kd) and `part.png` beside it, the names taken from the OBJ's stem.
// Written texture first, OBJ last, each atomically.
//
// GLB: binary glTF 2.0 with the PNG embedded (a buffer view, image/png). Vertex data is in mm; the one
// node scales by 0.001, so viewers that follow glTF's metres show the part at its real size. The
// material is pbrMetallicRoughness with the texture as base colour (sRGB), not metallic, roughness 0.6
// (finished wood); the sampler is trilinear with clamped edges.
#include <filesystem>
#include <vector>

#include "io/image.hpp"
#include "mesh/mesh.hpp"

namespace kerf {

// Returns the files written (OBJ, MTL, PNG). Throws InputError.
std::vector<std::filesystem::path> writePartObj(const std::filesystem::path& objPath, const Mesh& atlasMesh,
                                                const Image& texture);

// Throws InputError.
void writePartGlb(const std::filesystem::path& glbPath, const Mesh& atlasMesh, const Image& texture);

}  // namespace kerf
