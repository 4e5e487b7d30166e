// Parts (issue 7), the geometry: meshes read with assimp (OBJ, STL, PLY), the placement maths and the
// fit check (core/mesh/).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/glm.hpp>

#include "geometry/block.hpp"
#include "mesh/mesh_loader.hpp"
#include "mesh/mesh_topology.hpp"
#include "mesh/part_placement.hpp"
#include "part_meshes.hpp"
#include "test_files.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

fs::path folder(const std::string& name) {
  return kerf::testing::scratchFolder("part-mesh", name);
}

double surfaceArea(const Mesh& m) {
  double a = 0;
  for (const glm::uvec3& t : m.triangles)
    a += 0.5 *
         glm::length(glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]));
  return a;
}

// Signed volume (divergence theorem): positive when the triangles face outwards.
double volume(const Mesh& m) {
  double v = 0;
  for (const glm::uvec3& t : m.triangles)
    v += glm::dot(m.positions[t.x], glm::cross(m.positions[t.y], m.positions[t.z])) / 6.0;
  return v;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(MeshLoad, ObjBoxWithQuadsIsTriangulatedWithNormals) {
  const Mesh m = loadMesh(kerf::testing::writeBoxObj(folder("obj") / "box.obj", {10, 20, 30}));
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_NEAR(surfaceArea(m), 2 * (10 * 20 + 20 * 30 + 10 * 30), 1e-3);
  EXPECT_NEAR(volume(m), 10 * 20 * 30, 1e-2);
  const MeshBounds b = meshBounds(m.positions);
  EXPECT_EQ(b.min, glm::vec3(-5, -10, -15));
  EXPECT_EQ(b.max, glm::vec3(5, 10, 15));
  ASSERT_TRUE(m.hasNormals());
  // Box edges stay sharp (80° smoothing limit): every normal is an axis.
  for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
  for (const glm::vec3& n : m.normals)
    EXPECT_NEAR(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 1.0f, 1e-4f);
  EXPECT_EQ(m.name, "box.obj");
}

TEST(MeshLoad, StlAndPlyPrismsReadTheSameSurface) {
  const fs::path dir = folder("stl-ply");
  const Mesh stl = loadMesh(kerf::testing::writePrismStl(dir / "prism.stl", 8, 20, 24));
  const Mesh ply = loadMesh(kerf::testing::writePrismPly(dir / "prism.ply", 8, 20, 24));
  EXPECT_EQ(stl.triangles.size(), 24u * 4);
  EXPECT_EQ(ply.triangles.size(), 24u * 4);
  const double expectedVolume = 0.5 * 24 * 8 * 8 * std::sin(2 * M_PI / 24) * 20;
  EXPECT_NEAR(volume(stl), expectedVolume, 0.05);
  EXPECT_NEAR(volume(ply), expectedVolume, 0.05);
  EXPECT_NEAR(surfaceArea(stl), surfaceArea(ply), 1e-2);
  EXPECT_TRUE(stl.hasNormals());
  EXPECT_TRUE(ply.hasNormals());
}

TEST(MeshLoad, ErrorsNameTheFile) {
  const fs::path dir = folder("errors");
  EXPECT_NE(errorOf([&] { loadMesh(dir / "missing.obj"); }).find("missing.obj: no such file"),
            std::string::npos);
  std::ofstream(dir / "part.fbx") << "not a mesh";
  EXPECT_NE(errorOf([&] { loadMesh(dir / "part.fbx"); }).find("part.fbx: unknown format \".fbx\""),
            std::string::npos);
  std::ofstream(dir / "points.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::string noFaces = errorOf([&] { loadMesh(dir / "points.obj"); });
  EXPECT_NE(noFaces.find("points.obj has no faces"), std::string::npos) << noFaces;
  std::ofstream(dir / "garbage.stl") << "this is not an STL file at all";
  const std::string garbage = errorOf([&] { loadMesh(dir / "garbage.stl"); });
  EXPECT_NE(garbage.find("garbage.stl"), std::string::npos) << garbage;
  EXPECT_NE(garbage, "(no error)");
}

TEST(MeshTopology, ClosedBoxAndStlPrismWhoseCornersAreRepeatedPerTriangle) {
  const fs::path dir = folder("topology-closed");
  const MeshTopology box = meshTopology(loadMesh(kerf::testing::writeBoxObj(dir / "box.obj", {1, 2, 3})));
  EXPECT_TRUE(box.closed());
  EXPECT_EQ(box.edges, 18u);  // 12 box edges and 6 quad diagonals
  EXPECT_EQ(box.describeOpen(), "");
  const MeshTopology prism =
      meshTopology(loadMesh(kerf::testing::writePrismStl(dir / "prism.stl", 8, 20, 24)));
  EXPECT_TRUE(prism.closed());
  EXPECT_EQ(prism.edges, 24u * 6);
  EXPECT_EQ(prism.degenerateTriangles, 0u);
}

TEST(MeshTopology, BoxWithoutItsTopHasFourOpenEdges) {
  const fs::path file =
      kerf::testing::writeBoxesObj(folder("topology-open") / "tray.obj", {{{0, 0, 0}, {2, 2, 2}}}, 1);
  const MeshTopology t = meshTopology(loadMesh(file));  // open meshes load: a surface can be baked
  EXPECT_FALSE(t.closed());
  EXPECT_EQ(t.openEdges, 4u);
  EXPECT_EQ(t.nonManifoldEdges, 0u);
  EXPECT_NE(t.describeOpen().find("4 open edges (a hole or a surface, e.g. at "), std::string::npos)
      << t.describeOpen();
}

// Issue 21: assimp's normal generation and vertex joining were quadratic in the triangles around one
// vertex (an 80k-triangle cone took 32-41 s to load). The loader now does both itself by hashing; this
// checks the result on a cone whose apex and base centre are each on 10000 triangles. (Its load time is
// in kerf_bench, BM_LoadClosedCone: a test's verdict never depends on time.)
TEST(MeshLoad, HighValenceConeGetsSmoothSidesASharpRimAndSharedVertices) {
  constexpr int kSides = 10000;
  constexpr float kRadius = 10.0f, kHeight = 30.0f;
  const Mesh m = loadMesh(kerf::testing::writeConeObj(folder("cone") / "cone.obj", kRadius, kHeight, kSides));
  ASSERT_EQ(m.triangles.size(), 2u * kSides);
  // The apex and the base centre become one vertex each; every rim point two (its side normal and the
  // base's: the rim's 108-degree edge is sharper than the 80-degree smoothing limit).
  EXPECT_EQ(m.positions.size(), 2u * kSides + 2);
  ASSERT_TRUE(m.hasNormals());
  const MeshTopology topology = meshTopology(m);
  EXPECT_TRUE(topology.closed());
  EXPECT_EQ(topology.nonManifoldEdges, 0u);
  const double polygonArea = 0.5 * kSides * kRadius * kRadius * std::sin(2.0 * M_PI / kSides);
  EXPECT_NEAR(volume(m), polygonArea * kHeight / 3.0, 1e-3 * polygonArea * kHeight);
  const glm::vec3 side = glm::normalize(glm::vec3(kHeight, 0.0f, kRadius));  // the side's normal at +x
  std::size_t apex = 0, base = 0, rimSide = 0;
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    const glm::vec3 p = m.positions[v], n = m.normals[v];
    ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    if (p == glm::vec3(0, 0, kHeight)) {
      ++apex;
      EXPECT_GT(n.z, 0.999f);  // the mean of the sides around the tip
    } else if (p == glm::vec3(0.0f)) {
      ++base;
      EXPECT_LT(n.z, -0.999f);
    } else if (n.z > 0.0f) {
      ++rimSide;  // a rim point's side normal: tilted out as the cone's side is
      const float azimuth = std::atan2(p.y, p.x);
      const glm::vec3 expected(side.x * std::cos(azimuth), side.x * std::sin(azimuth), side.z);
      EXPECT_GT(glm::dot(n, expected), 0.9999f);
    } else {
      EXPECT_LT(n.z, -0.999f);  // a rim point's base normal
    }
  }
  EXPECT_EQ(apex, 1u);
  EXPECT_EQ(base, 1u);
  EXPECT_EQ(rimSide, static_cast<std::size_t>(kSides));
}

TEST(MeshLoad, NonManifoldMeshIsRefusedSayingWhere) {
  // Two boxes touching along the edge x = 1, y = 1: four triangles meet there.
  const fs::path file = kerf::testing::writeBoxesObj(folder("topology-non-manifold") / "two_boxes.obj",
                                                     {{{0, 0, 0}, {1, 1, 1}}, {{1, 1, 0}, {2, 2, 1}}});
  const std::string error = errorOf([&] { loadMesh(file); });
  EXPECT_NE(error.find("two_boxes.obj is not the surface of a solid: 1 edge is shared by more than two "
                       "triangles (e.g. at 1, 1, 0.5 in the file's units)"),
            std::string::npos)
      << error;
}

TEST(PartPlacement, ScaleThenRotateXYZThenTranslate) {
  PartPlacement p;
  p.scale = 2.0f;
  p.rotationDeg = {90, 0, 0};
  p.translationMm = {1, 2, 3};
  // x turn by 90°: y -> z. (0, 1, 0) scaled to (0, 2, 0), turned to (0, 0, 2), moved to (1, 2, 5).
  glm::vec3 q = glm::vec3(placementMatrix(p, {}) * glm::vec4(0, 1, 0, 1));
  EXPECT_NEAR(glm::distance(q, glm::vec3(1, 2, 5)), 0.0f, 1e-5f);
  // Order: x first, then z. (0, 1, 0) -x90-> (0, 0, 1) -z90-> (0, 0, 1); the reverse order would give
  // (-1, 0, 0) -x90-> (-1, 0, 0).
  p = {};
  p.rotationDeg = {90, 0, 90};
  q = glm::vec3(placementMatrix(p, {}) * glm::vec4(0, 1, 0, 1));
  EXPECT_NEAR(glm::distance(q, glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
  q = glm::vec3(placementMatrix(p, {}) * glm::vec4(1, 0, 0, 1));  // x -> x -> y
  EXPECT_NEAR(glm::distance(q, glm::vec3(0, 1, 0)), 0.0f, 1e-5f);
  // y by 90°: z -> x (right-handed).
  p = {};
  p.rotationDeg = {0, 90, 0};
  q = glm::vec3(placementMatrix(p, {}) * glm::vec4(0, 0, 1, 1));
  EXPECT_NEAR(glm::distance(q, glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
}

TEST(PartPlacement, CentreInBlockCentresTheTurnedBoundingBox) {
  // A mesh off to one side, turned: its box's centre lands on the translation.
  const std::vector<glm::vec3> pts = {{10, 0, 0}, {14, 2, 0}, {12, 6, 1}, {11, 1, 3}};
  PartPlacement p;
  p.centreInBlock = true;
  p.rotationDeg = {10, 20, 30};
  p.scale = 1.5f;
  p.translationMm = {1, -2, 0.5f};
  Mesh m;
  m.positions = pts;
  m.normals = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Mesh placed = placeMesh(m, p);
  EXPECT_NEAR(glm::distance(meshBounds(placed.positions).centre(), p.translationMm), 0.0f, 1e-4f);
  // Normals turn with the part and stay unit length.
  EXPECT_NEAR(glm::distance(placed.normals[0], placementRotation(p.rotationDeg) * glm::vec3(1, 0, 0)), 0.0f,
              1e-5f);
  // Distances scale by 1.5.
  EXPECT_NEAR(glm::distance(placed.positions[0], placed.positions[1]), 1.5f * glm::distance(pts[0], pts[1]),
              1e-4f);
}

TEST(PartPlacement, NonFiniteOrBadScaleIsAnError) {
  PartPlacement p;
  p.translationMm.y = std::nanf("");
  EXPECT_NE(errorOf([&] { validatePlacement(p); }).find("position must be three numbers"), std::string::npos);
  p = {};
  p.rotationDeg.z = INFINITY;
  EXPECT_NE(errorOf([&] { placementMatrix(p, {}); }).find("rotation"), std::string::npos);
  p = {};
  p.scale = 0.0f;
  EXPECT_NE(errorOf([&] { validatePlacement(p); }).find("scale must be a positive number"),
            std::string::npos);
}

TEST(PartFit, ReportsWhichFaceAndByHowMuch) {
  const Block block(glm::vec3(40, 60, 20));
  // A 10 x 10 x 10 box at the centre: 15 mm clearance on x, 25 on y, 5 on z.
  std::vector<glm::vec3> box;
  for (int i = 0; i < 8; ++i)
    box.push_back({(i & 1) ? 5.f : -5.f, (i & 2) ? 5.f : -5.f, (i & 4) ? 5.f : -5.f});
  PartFit fit = checkPartFit(block, box);
  EXPECT_TRUE(fit.fits());
  EXPECT_FLOAT_EQ(fit.clearanceMm[int(FaceId::A)], 5.0f);
  EXPECT_FLOAT_EQ(fit.clearanceMm[int(FaceId::E)], 15.0f);
  EXPECT_EQ(fit.describe(), "the part fits in the block (at least 5.0 mm of wood around it)");

  // Moved 18 mm along +x and 7 along -z: 3 mm beyond E (+x) and 2 mm beyond F (-z).
  for (glm::vec3& p : box) p += glm::vec3(18, 0, -7);
  fit = checkPartFit(block, box);
  EXPECT_FALSE(fit.fits());
  EXPECT_NEAR(fit.outsideMm[int(FaceId::E)], 3.0f, 1e-5f);
  EXPECT_NEAR(fit.outsideMm[int(FaceId::F)], 2.0f, 1e-5f);
  EXPECT_EQ(fit.outsideMm[int(FaceId::C)], 0.0f);
  EXPECT_NEAR(fit.worstOutsideMm(), 3.0f, 1e-5f);
  EXPECT_EQ(fit.describe(),
            "the part sticks out of the block by 3.0 mm at face E (+x) and 2.0 mm at face F (-z)");

  // Touching a face exactly still fits.
  std::vector<glm::vec3> flush = {{20, 0, 0}, {-20, 30, -10}};
  EXPECT_TRUE(checkPartFit(block, flush).fits());
}
