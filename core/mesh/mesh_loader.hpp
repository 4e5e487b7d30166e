#pragma once
// Reading a part's mesh from OBJ, STL (ASCII or binary) or PLY with assimp. All meshes and nodes of the
// file are merged into one, in the file's root frame; polygons are triangulated, points and lines
// dropped. A file without normals gets them computed (smooth up to 80°, so edges of a box stay sharp).
#include <filesystem>

#include "mesh/mesh.hpp"

namespace kerf {

// The extensions loadMesh accepts (lower case, with the dot).
bool isMeshExtension(const std::string& lowerExtension);

// Throws InputError naming the file: unreadable, unknown format, no triangles, non-finite coordinates,
// non-manifold edges (mesh_topology.hpp).
Mesh loadMesh(const std::filesystem::path& path);

}  // namespace kerf
