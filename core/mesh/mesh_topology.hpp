#pragma once
// Is a part's mesh the surface of a solid? Edges are counted between corners welded by position (files
// such as STL repeat each corner per triangle). A closed solid has every edge on exactly two triangles;
// an edge on one triangle is open (a hole, or a surface rather than a solid); an edge on three or more
// is non-manifold (two solids touching along an edge, internal faces, a bad boolean in the CAD program).
#include <cstddef>
#include <glm/vec3.hpp>
#include <string>

#include "mesh/mesh.hpp"

namespace kerf {

struct MeshTopology {
  std::size_t edges = 0, openEdges = 0, nonManifoldEdges = 0, degenerateTriangles = 0;
  glm::vec3 firstNonManifold{0.0f};  // the midpoint of one non-manifold edge, for messages
  glm::vec3 firstOpen{0.0f};         // the midpoint of one open edge

  bool closed() const { return openEdges == 0 && nonManifoldEdges == 0; }
  // "12 open edges (a hole or a surface, e.g. at 3.5, 0, 20 mm)"; empty when closed.
  std::string describeOpen() const;
};

MeshTopology meshTopology(const Mesh& mesh);

}  // namespace kerf
