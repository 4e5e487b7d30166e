#pragma once
// Vertex normals and vertex joining for loaded meshes, done here in linear time instead of by assimp's
// post-processing (aiProcess_GenSmoothNormals, aiProcess_JoinIdenticalVertices), whose cost grows with the
// square of the triangles around one vertex: an 80k-triangle closed cone (one apex on 40k triangles) took
// 32-41 s to load (issue 21).
#include <vector>

#include "mesh/mesh.hpp"

namespace kerf {

// Gives every corner of `mesh` whose vertex has needsNormal[v] a smooth normal: the area-weighted sum of
// the normals of the triangles around its position (corners welded by exact position) that lie within
// maxAngleDeg of the corner's own triangle, so edges sharper than that stay sharp (a box keeps flat
// faces). That rule is quadratic in a vertex's valence, so above kExactValence triangles around one
// position the corner takes the mean normal of all of them when it lies within maxAngleDeg of its own
// triangle, and the triangle's normal otherwise. Vertices with needsNormal[v] false keep their normal.
// Then corners equal in position, normal and texture coordinate are joined into one vertex (hashing).
// needsNormal.size() must equal mesh.positions.size(); normals and uvs are resized to match.
inline constexpr int kExactValence = 64;
void smoothNormalsAndJoinVertices(Mesh& mesh, const std::vector<bool>& needsNormal, float maxAngleDeg);

}  // namespace kerf
