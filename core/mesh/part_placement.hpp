#pragma once
// Where a part sits in the block (issue 7): a mesh point m (file units, read as mm) goes to the block
// point (docs/coordinates.md)
//
//   p = translation + Rz(rz) · Ry(ry) · Rx(rx) · (scale · m - pivot)
//
// i.e. scaled, then turned about the block's x axis by rx, then about y by ry, then about z by rz
// (degrees, right-handed: counter-clockwise looking down the axis towards the origin), then moved.
// pivot is 0, or with centreInBlock the centre of the scaled mesh's bounding box, so the translation is
// the offset of the part's centre from the block centre. With centreInBlock the centre is taken after
// turning: the turned part's bounding box is centred at the translation.
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

#include "geometry/block.hpp"
#include "mesh/mesh.hpp"

namespace kerf {

struct PartPlacement {
  glm::vec3 translationMm{0.0f};
  glm::vec3 rotationDeg{0.0f};  // about x, then y, then z (block axes)
  float scale = 1.0f;           // uniform; > 0
  bool centreInBlock = false;
};

// Throws InputError for a coordinate, angle or scale that is not a finite number, or a scale <= 0.
void validatePlacement(const PartPlacement& placement);

// The rotation Rz · Ry · Rx.
glm::mat3 placementRotation(glm::vec3 rotationDeg);

// The full map from mesh coordinates to block mm for this mesh (its bounds matter with centreInBlock).
glm::mat4 placementMatrix(const PartPlacement& placement, const std::vector<glm::vec3>& meshPositions);

// The mesh moved into the block: positions mapped, normals turned. Texture coordinates are kept.
Mesh placeMesh(const Mesh& mesh, const PartPlacement& placement);

// Whether every vertex of a placed mesh lies in the block, and by how much it sticks out of each face.
struct PartFit {
  // mm beyond each face, indexed by FaceId (A = +z, B = +y, C = -x, D = -y, E = +x, F = -z); 0 inside.
  float outsideMm[6] = {0, 0, 0, 0, 0, 0};
  // Space left between the part's bounding box and each face (negative where it sticks out).
  float clearanceMm[6] = {0, 0, 0, 0, 0, 0};
  MeshBounds bounds;  // of the placed part, block mm
  bool fits() const;
  float worstOutsideMm() const;
  // One line for the user, e.g. "the part fits in the block (at least 1.5 mm of wood around it)" or
  // "the part sticks out of the block by 3.2 mm at face E (+x) and 0.4 mm at face B (+y)".
  std::string describe() const;
};
// toleranceMm: how far a vertex may lie outside and still count as inside (rounding of the file).
PartFit checkPartFit(const Block& block, const std::vector<glm::vec3>& placedPositions,
                     float toleranceMm = 1e-3f);

}  // namespace kerf
