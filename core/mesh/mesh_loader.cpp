#include "mesh/mesh_loader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <sstream>
#include <system_error>

#include "io/input_file.hpp"
#include "mesh/mesh_normals.hpp"
#include "mesh/mesh_topology.hpp"
#include "util/error.hpp"
#include "util/file_extension.hpp"

namespace kerf {

MeshBounds meshBounds(const std::vector<glm::vec3>& positions) {
  MeshBounds b;
  if (positions.empty()) return b;
  b.min = b.max = positions.front();
  for (const glm::vec3& p : positions) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

bool isMeshExtension(const std::string& e) {
  return e == ".obj" || e == ".stl" || e == ".ply";
}

namespace {

// Edges sharper than this stay sharp in the normals made for a mesh without them.
constexpr float kSmoothingAngleDeg = 80.0f;

glm::mat4 toGlm(const aiMatrix4x4& m) {
  // aiMatrix4x4 is row-major (a1..a4 is the first row); glm is column-major.
  return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4,
                   m.d4);
}

// needsNormal: one flag per vertex appended, true where the file gave no normal.
void appendMesh(Mesh& out, std::vector<bool>& needsNormal, const aiMesh& in, const glm::mat4& transform) {
  if (!(in.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return;
  const auto base = static_cast<unsigned>(out.positions.size());
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  const bool withUvs = in.HasTextureCoords(0);
  for (unsigned i = 0; i < in.mNumVertices; ++i) {
    const aiVector3D& p = in.mVertices[i];
    out.positions.push_back(glm::vec3(transform * glm::vec4(p.x, p.y, p.z, 1.0f)));
    glm::vec3 n(0.0f, 0.0f, 1.0f);
    if (in.HasNormals()) {
      const glm::vec3 t = normalMatrix * glm::vec3(in.mNormals[i].x, in.mNormals[i].y, in.mNormals[i].z);
      if (glm::length(t) > 0.0f && std::isfinite(glm::length(t))) n = glm::normalize(t);
    }
    out.normals.push_back(n);
    needsNormal.push_back(!in.HasNormals());
    // Texture coordinates are kept for information only (the bake makes its own atlas); assimp's v is
    // up, Kerf's is down.
    out.uvs.push_back(withUvs ? glm::vec2(in.mTextureCoords[0][i].x, 1.0f - in.mTextureCoords[0][i].y)
                              : glm::vec2(0.0f));
  }
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (face.mNumIndices != 3) continue;
    out.triangles.push_back(
        glm::uvec3(base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]));
  }
}

void appendNode(Mesh& out, std::vector<bool>& needsNormal, const aiScene& scene, const aiNode& node,
                const glm::mat4& parent) {
  const glm::mat4 transform = parent * toGlm(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i)
    appendMesh(out, needsNormal, *scene.mMeshes[node.mMeshes[i]], transform);
  for (unsigned i = 0; i < node.mNumChildren; ++i)
    appendNode(out, needsNormal, scene, *node.mChildren[i], transform);
}

}  // namespace

Mesh loadMesh(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError("cannot read mesh " + name + ": no such file");
  checkInputFile(path, "mesh", kMaxMeshFileBytes);  // regular files only: a FIFO must not block
  if (!isMeshExtension(lowerExtension(path)))
    throw InputError("cannot read mesh " + name + ": unknown format \"" + lowerExtension(path) +
                     "\" (use .obj, .stl or .ply)");
  Assimp::Importer importer;
  // Points and lines are removed; polygons become triangles. Missing normals and shared vertices are
  // made by smoothNormalsAndJoinVertices below, in linear time: assimp's GenSmoothNormals and
  // JoinIdenticalVertices are quadratic in the triangles around one vertex (mesh_normals.hpp).
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(name, aiProcess_Triangulate | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) {
    std::string why = importer.GetErrorString();
    std::string lower = why;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    // A file of points or lines loses all its meshes when those are dropped.
    if (lower.find("no meshes") != std::string::npos)
      throw InputError("mesh " + name + " has no faces (triangles or polygons)");
    throw InputError("cannot read mesh " + name + ": " + why);
  }
  Mesh mesh;
  mesh.name = path.filename().string();
  std::vector<bool> needsNormal;
  appendNode(mesh, needsNormal, *scene, *scene->mRootNode, glm::mat4(1.0f));
  if (mesh.triangles.empty()) throw InputError("mesh " + name + " has no faces (triangles or polygons)");
  for (const glm::vec3& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError("mesh " + name + " has a vertex with a coordinate that is not a number");
  // A part without area (every triangle degenerate) is no surface to cut or texture (issue 21: such a
  // mesh was exported). Degenerate slivers among real triangles are common in CAD output and are kept.
  double area = 0.0;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  glm::dvec3 lo(mesh.positions.front()), hi = lo;
  for (const glm::vec3& p : mesh.positions)
    lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
  const double extent = glm::length(hi - lo);
  if (!(area > 1e-9 * extent * extent)) {  // relative: corners on a line up to float rounding
    throw InputError("mesh " + name + " has no area: all its " + std::to_string(mesh.triangles.size()) +
                     " triangles are degenerate (their corners lie on a line or a point)");
  }
  smoothNormalsAndJoinVertices(mesh, needsNormal, kSmoothingAngleDeg);
  // A non-manifold part has no inside and outside for the CNC planner, and the bake would texture its
  // internal faces: refuse it, saying where. Open meshes are only warned about (exportPart).
  if (const MeshTopology topology = meshTopology(mesh); topology.nonManifoldEdges > 0) {
    std::ostringstream s;
    s.precision(4);
    const glm::vec3 p = topology.firstNonManifold;
    s << "mesh " << name << " is not the surface of a solid: " << topology.nonManifoldEdges
      << (topology.nonManifoldEdges == 1 ? " edge is" : " edges are")
      << " shared by more than two triangles (e.g. at " << p.x << ", " << p.y << ", " << p.z
      << " in the file's units); repair it in the CAD program (Blender: Select > All by Trait > Non "
         "Manifold)";
    throw InputError(s.str());
  }
  if (!std::any_of(mesh.uvs.begin(), mesh.uvs.end(), [](glm::vec2 t) { return t != glm::vec2(0.0f); }))
    mesh.uvs.clear();
  return mesh;
}

}  // namespace kerf
