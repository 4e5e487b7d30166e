#include "mesh/part_placement.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>

#include "util/error.hpp"

namespace kerf {

void validatePlacement(const PartPlacement& p) {
  const auto finite = [](glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  if (!finite(p.translationMm)) throw InputError("the part's position must be three numbers (mm)");
  if (!finite(p.rotationDeg)) throw InputError("the part's rotation must be three numbers (degrees)");
  if (!std::isfinite(p.scale) || !(p.scale > 0.0f))
    throw InputError("the part's scale must be a positive number");
}

glm::mat3 placementRotation(glm::vec3 rotationDeg) {
  const glm::vec3 r = glm::radians(rotationDeg);
  const glm::mat4 rx = glm::rotate(glm::mat4(1.0f), r.x, glm::vec3(1, 0, 0));
  const glm::mat4 ry = glm::rotate(glm::mat4(1.0f), r.y, glm::vec3(0, 1, 0));
  const glm::mat4 rz = glm::rotate(glm::mat4(1.0f), r.z, glm::vec3(0, 0, 1));
  return glm::mat3(rz * ry * rx);
}

glm::mat4 placementMatrix(const PartPlacement& placement, const std::vector<glm::vec3>& meshPositions) {
  validatePlacement(placement);
  const glm::mat3 turn = placementRotation(placement.rotationDeg) * placement.scale;
  glm::vec3 pivotInBlock(0.0f);  // where the turned pivot lands before translation
  if (placement.centreInBlock && !meshPositions.empty()) {
    std::vector<glm::vec3> turned(meshPositions.size());
    std::transform(meshPositions.begin(), meshPositions.end(), turned.begin(),
                   [&](glm::vec3 m) { return turn * m; });
    pivotInBlock = meshBounds(turned).centre();
  }
  glm::mat4 m(turn);
  m[3] = glm::vec4(placement.translationMm - pivotInBlock, 1.0f);
  return m;
}

Mesh placeMesh(const Mesh& mesh, const PartPlacement& placement) {
  const glm::mat4 m = placementMatrix(placement, mesh.positions);
  const glm::mat3 rotation = placementRotation(placement.rotationDeg);
  Mesh placed = mesh;
  for (glm::vec3& p : placed.positions) p = glm::vec3(m * glm::vec4(p, 1.0f));
  for (glm::vec3& n : placed.normals) n = rotation * n;
  return placed;
}

bool PartFit::fits() const {
  return worstOutsideMm() <= 0.0f;
}

float PartFit::worstOutsideMm() const {
  return *std::max_element(std::begin(outsideMm), std::end(outsideMm));
}

std::string PartFit::describe() const {
  static const char* const kAxis[6] = {"+z", "+y", "-x", "-y", "+x", "-z"};
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(1);
  if (fits()) {
    const float least = *std::min_element(std::begin(clearanceMm), std::end(clearanceMm));
    s << "the part fits in the block (at least " << std::max(0.0f, least) << " mm of wood around it)";
    return s.str();
  }
  // Worst side first.
  std::vector<int> sides;
  for (int f = 0; f < 6; ++f)
    if (outsideMm[f] > 0.0f) sides.push_back(f);
  std::sort(sides.begin(), sides.end(), [&](int a, int b) { return outsideMm[a] > outsideMm[b]; });
  s << "the part sticks out of the block by ";
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (i > 0) s << (i + 1 == sides.size() ? " and " : ", ");
    if (outsideMm[sides[i]] < 0.05f)
      s << "less than 0.1";
    else
      s << outsideMm[sides[i]];
    s << " mm at face " << faceLetter(static_cast<FaceId>(sides[i])) << " (" << kAxis[sides[i]] << ")";
  }
  return s.str();
}

PartFit checkPartFit(const Block& block, const std::vector<glm::vec3>& placed, float toleranceMm) {
  PartFit fit;
  fit.bounds = meshBounds(placed);
  const glm::vec3 half = 0.5f * block.size();
  // Per face: how far the extreme vertex lies beyond the face plane (positive = outside).
  const float beyond[6] = {
      fit.bounds.max.z - half.z,   // A +z
      fit.bounds.max.y - half.y,   // B +y
      -half.x - fit.bounds.min.x,  // C -x
      -half.y - fit.bounds.min.y,  // D -y
      fit.bounds.max.x - half.x,   // E +x
      -half.z - fit.bounds.min.z,  // F -z
  };
  for (int f = 0; f < 6; ++f) {
    fit.clearanceMm[f] = -beyond[f];
    fit.outsideMm[f] = beyond[f] > toleranceMm ? beyond[f] : 0.0f;
  }
  return fit;
}

}  // namespace kerf
