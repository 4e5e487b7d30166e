// Parts (issue 7), the texture: the UV atlas, the bake against the wood model, and the OBJ+MTL+PNG and
// binary glTF files read back with assimp, tinygltf and OpenImageIO.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <assimp/Importer.hpp>
#include <cstring>
#include <fstream>
#include <glm/glm.hpp>

#include "demo/demo_block.hpp"
#include "export/export_job.hpp"
#include "export/part_export.hpp"
#include "image/image_difference.hpp"
#include "mesh/bake_part_texture.hpp"
#include "mesh/mesh_loader.hpp"
#include "mesh/uv_atlas.hpp"
#include "part_meshes.hpp"
#include "render/wood_model.hpp"
#include "test_files.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

fs::path folder(const std::string& name) {
  return kerf::testing::scratchFolder("part-export", name);
}

const WoodModel& demoModel() {
  static const Project project = demoProject();
  static const WoodModel model(project);
  return model;
}

// The demo block is 40 mm; a 20 x 12 x 28 mm box turned a little, and a 24-sided prism, both inside.
Mesh placedBox(const fs::path& dir) {
  PartPlacement p;
  p.rotationDeg = {0, 25, 10};
  p.translationMm = {1, -2, 0};
  return placeMesh(loadMesh(kerf::testing::writeBoxObj(dir / "box.obj", {20, 12, 28})), p);
}
Mesh placedPrism(const fs::path& dir) {
  PartPlacement p;
  p.rotationDeg = {30, 0, 0};
  return placeMesh(loadMesh(kerf::testing::writePrismStl(dir / "prism.stl", 9, 24, 24)), p);
}

float triangleArea2(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

// Bilinear lookup of the texture at uv (v down), texel centres at +0.5.
glm::vec3 sample(const Image& image, glm::vec2 uv) {
  const glm::vec2 t = uv * glm::vec2(image.width, image.height) - 0.5f;
  const glm::ivec2 i = glm::ivec2(glm::floor(t));
  const glm::vec2 f = t - glm::vec2(i);
  glm::vec3 c(0.0f);
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const int x = std::clamp(i.x + dx, 0, image.width - 1), y = std::clamp(i.y + dy, 0, image.height - 1);
      const float* p = image.pixel(x, y);
      c += glm::vec3(p[0], p[1], p[2]) * (dx ? f.x : 1 - f.x) * (dy ? f.y : 1 - f.y);
    }
  return c;
}

// Texel centres of the atlas that lie strictly inside two triangles (0 for a one-to-one atlas).
int overlappingTexels(const UvAtlas& atlas) {
  const int side = atlas.resolution;
  std::vector<int> owner(std::size_t(side) * side, -1);
  int overlaps = 0;
  for (std::size_t t = 0; t < atlas.mesh.triangles.size(); ++t) {
    const glm::uvec3 tri = atlas.mesh.triangles[t];
    const glm::vec2 a = atlas.mesh.uvs[tri.x] * float(side), b = atlas.mesh.uvs[tri.y] * float(side),
                    c = atlas.mesh.uvs[tri.z] * float(side);
    const float area = triangleArea2(a, b, c);
    if (std::abs(area) < 1e-9f) continue;
    const glm::vec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    for (int y = std::max(0, int(lo.y)); y <= std::min(side - 1, int(hi.y)); ++y)
      for (int x = std::max(0, int(lo.x)); x <= std::min(side - 1, int(hi.x)); ++x) {
        const glm::vec2 q(x + 0.5f, y + 0.5f);
        const glm::vec3 w(triangleArea2(b, c, q) / area, triangleArea2(c, a, q) / area,
                          triangleArea2(a, b, q) / area);
        if (w.x <= 1e-4f || w.y <= 1e-4f || w.z <= 1e-4f) continue;
        int& o = owner[std::size_t(y) * side + x];
        if (o >= 0) ++overlaps;
        o = int(t);
      }
  }
  return overlaps;
}

// A helical ramp (radius 4 to 8 mm, two turns, rising 1.5 mm a turn): one connected piece whose
// triangles all face +y and whose projection along y covers itself twice.
Mesh helicalRamp() {
  Mesh m;
  m.name = "ramp";
  const int steps = 64;
  for (int i = 0; i <= steps; ++i) {
    const float a = 4.0f * float(M_PI) * i / steps, y = 1.5f * a / (2.0f * float(M_PI)) - 1.5f;
    for (float r : {4.0f, 8.0f}) m.positions.push_back({r * std::cos(a), y, -r * std::sin(a)});
  }
  for (unsigned i = 0; i < unsigned(steps); ++i) {
    m.triangles.push_back({2 * i, 2 * i + 1, 2 * i + 3});
    m.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 2});
  }
  return m;
}

float maxDifference(glm::vec3 a, glm::vec3 b) {
  const glm::vec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z});
}

}  // namespace

TEST(PartAtlas, TrianglesInsideTheUnitSquareWithoutOverlapAndWithPadding) {
  const fs::path dir = folder("atlas");
  for (const Mesh& placed : {placedBox(dir), placedPrism(dir)}) {
    UvAtlasOptions options;
    options.resolution = 256;
    const UvAtlas atlas = buildUvAtlas(placed, options);
    ASSERT_EQ(atlas.mesh.triangles.size(), placed.triangles.size());
    EXPECT_EQ(atlas.padding, 2);
    EXPECT_GT(atlas.texelsPerMm, 0.5f);  // the part fills a good share of the square
    // Positions and normals are the placed mesh's, copied.
    for (std::size_t v = 0; v < atlas.mesh.positions.size(); ++v) {
      EXPECT_EQ(atlas.mesh.positions[v], placed.positions[atlas.sourceVertex[v]]);
      EXPECT_EQ(atlas.mesh.normals[v], placed.normals[atlas.sourceVertex[v]]);
    }
    // Every uv inside [0, 1]^2 and inside its chart's rectangle, at least `padding` texels from its edge;
    // every triangle keeps its shape (uniform texels per mm) and is not turned over.
    for (std::size_t t = 0; t < atlas.mesh.triangles.size(); ++t) {
      const glm::uvec3 tri = atlas.mesh.triangles[t];
      const UvAtlas::Chart& chart = atlas.charts[atlas.chartOfTriangle[t]];
      glm::vec2 uv[3];
      for (int k = 0; k < 3; ++k) {
        uv[k] = atlas.mesh.uvs[tri[k]];
        EXPECT_GE(uv[k].x, 0.0f);
        EXPECT_LE(uv[k].x, 1.0f);
        EXPECT_GE(uv[k].y, 0.0f);
        EXPECT_LE(uv[k].y, 1.0f);
        const glm::vec2 texel = uv[k] * float(atlas.resolution);
        EXPECT_GE(texel.x, chart.x + atlas.padding);
        EXPECT_LE(texel.x, chart.x + chart.width - atlas.padding);
        EXPECT_GE(texel.y, chart.y + atlas.padding);
        EXPECT_LE(texel.y, chart.y + chart.height - atlas.padding);
      }
      const glm::vec3 p0 = atlas.mesh.positions[tri.x], p1 = atlas.mesh.positions[tri.y],
                      p2 = atlas.mesh.positions[tri.z];
      const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
      // The texel-space area is the area projected along the chart axis times texels/mm squared.
      const float projected = std::abs(n[chart.axis / 2]);
      const float texelArea =
          std::abs(triangleArea2(uv[0], uv[1], uv[2])) * atlas.resolution * atlas.resolution;
      EXPECT_NEAR(texelArea, projected * atlas.texelsPerMm * atlas.texelsPerMm, 1e-3f * (1 + texelArea));
      EXPECT_GE(std::abs(n[chart.axis / 2]), 0.577f * glm::length(n) - 1e-4f);  // dominant axis
    }
    EXPECT_EQ(overlappingTexels(atlas), 0);
    // Chart rectangles are disjoint and inside the texture.
    for (std::size_t a = 0; a < atlas.charts.size(); ++a) {
      const UvAtlas::Chart& ca = atlas.charts[a];
      EXPECT_GE(ca.x, 0);
      EXPECT_GE(ca.y, 0);
      EXPECT_LE(ca.x + ca.width, atlas.resolution);
      EXPECT_LE(ca.y + ca.height, atlas.resolution);
      for (std::size_t b = a + 1; b < atlas.charts.size(); ++b) {
        const UvAtlas::Chart& cb = atlas.charts[b];
        const bool apart = ca.x + ca.width <= cb.x || cb.x + cb.width <= ca.x || ca.y + ca.height <= cb.y ||
                           cb.y + cb.height <= ca.y;
        EXPECT_TRUE(apart) << "charts " << a << " and " << b << " overlap";
      }
    }
  }
}

TEST(PartAtlas, BoxHasSixChartsAndPrismConnectsItsSideAcrossRepeatedStlVertices) {
  const fs::path dir = folder("charts");
  EXPECT_EQ(buildUvAtlas(placeMesh(loadMesh(kerf::testing::writeBoxObj(dir / "b.obj", {10, 10, 10})), {}))
                .charts.size(),
            6u);
  // Unturned prism along y: caps are one chart each; the 24 sides fall into the 4 classes ±x, ±z, each
  // class one connected strip (STL repeats vertices per facet, which the atlas welds by position).
  const UvAtlas prism =
      buildUvAtlas(placeMesh(loadMesh(kerf::testing::writePrismStl(dir / "p.stl", 9, 24, 24)), {}));
  EXPECT_EQ(prism.charts.size(), 6u);
}

TEST(PartAtlas, APieceThatWindsOverItselfIsSplitSoNoTexelIsShared) {
  const Mesh ramp = helicalRamp();
  UvAtlasOptions options;
  options.resolution = 512;
  const UvAtlas atlas = buildUvAtlas(ramp, options);
  // Projected along y as one chart, the two turns would share texels; split, none is shared.
  EXPECT_EQ(atlas.charts.size(), ramp.triangles.size());
  EXPECT_EQ(overlappingTexels(atlas), 0);
  for (const UvAtlas::Chart& c : atlas.charts) EXPECT_EQ(c.axis, 2);  // +y
  // One turn alone does not overlap: one chart.
  Mesh turn = ramp;
  turn.triangles.resize(ramp.triangles.size() / 2 - 2);
  EXPECT_EQ(buildUvAtlas(turn, options).charts.size(), 1u);
}

TEST(PartAtlas, TooManyPiecesForTheResolutionIsAnError) {
  Mesh scattered;
  scattered.name = "dust.obj";
  for (int i = 0; i < 2000; ++i) {  // 2000 separate triangles need 2000 * (1 + 2 * 2)^2 texels > 16^2
    const glm::vec3 o(i * 3.0f, 0, 0);
    scattered.positions.insert(scattered.positions.end(),
                               {o, o + glm::vec3(1, 0, 0), o + glm::vec3(0, 1, 0)});
    scattered.triangles.push_back(glm::uvec3(3 * i, 3 * i + 1, 3 * i + 2));
  }
  UvAtlasOptions options;
  options.resolution = 16;
  try {
    buildUvAtlas(scattered, options);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dust.obj has 2000 separate pieces, too many for a 16 px texture"),
              std::string::npos)
        << e.what();
  }
}

TEST(PartBake, TextureAtEachVertexAndInsideTrianglesIsTheWoodThere) {
  const fs::path dir = folder("bake");
  for (const Mesh& placed : {placedBox(dir), placedPrism(dir)}) {
    UvAtlasOptions options;
    options.resolution = 512;
    const UvAtlas atlas = buildUvAtlas(placed, options);
    const BakedTexture baked = bakePartTexture(demoModel(), atlas);
    ASSERT_EQ(baked.image.width, 512);
    // Each texel on the part: a model evaluation; the gutter is not evaluated.
    EXPECT_GT(baked.samples, 512u * 512u / 4);
    EXPECT_LT(baked.samples, 512u * 512u);

    // At a vertex's uv, the texture (bilinear, as a viewer samples it) is the wood at the vertex's block
    // position. Texels are ~0.1 mm here; the wood's colour changes little over that except at pores and
    // ring edges, so the mean is tight and single vertices may differ more (a vertex on the sharp rim of a
    // pore, a hole since issue 16, measured 0.21; 0.30 still catches a texel from another place).
    double sum = 0;
    for (std::size_t v = 0; v < atlas.mesh.positions.size(); ++v) {
      const float d = maxDifference(sample(baked.image, atlas.mesh.uvs[v]),
                                    demoModel().evaluate(atlas.mesh.positions[v]).color);
      EXPECT_LT(d, 0.3f) << "vertex " << v;
      sum += d;
    }
    EXPECT_LT(sum / atlas.mesh.positions.size(), 0.03);

    // Random points inside triangles: exact texel centres of the owning triangle are the model's colour.
    std::size_t checked = 0;
    for (int y = 0; y < 512; y += 7)
      for (int x = 0; x < 512; x += 5) {
        const int t = baked.owner[std::size_t(y) * 512 + x];
        if (t < 0) continue;
        const glm::uvec3 tri = atlas.mesh.triangles[t];
        const glm::vec2 q = (glm::vec2(x, y) + 0.5f) / 512.0f;
        const glm::vec2 a = atlas.mesh.uvs[tri.x], b = atlas.mesh.uvs[tri.y], c = atlas.mesh.uvs[tri.z];
        const float area = triangleArea2(a, b, c);
        const glm::vec3 w(triangleArea2(b, c, q) / area, triangleArea2(c, a, q) / area,
                          triangleArea2(a, b, q) / area);
        const glm::vec3 p = w.x * atlas.mesh.positions[tri.x] + w.y * atlas.mesh.positions[tri.y] +
                            w.z * atlas.mesh.positions[tri.z];
        const float* texel = baked.image.pixel(x, y);
        EXPECT_LT(maxDifference(glm::vec3(texel[0], texel[1], texel[2]), demoModel().evaluate(p).color),
                  1e-4f);
        ++checked;
      }
    EXPECT_GT(checked, 500u);
  }
}

TEST(PartBake, SupersamplingAveragesPointsSpreadOverTheTexel) {
  const fs::path dir = folder("supersampling");
  UvAtlasOptions options;
  options.resolution = 64;
  const UvAtlas atlas = buildUvAtlas(placedBox(dir), options);
  const BakedTexture one = bakePartTexture(demoModel(), atlas, 1);
  const BakedTexture three = bakePartTexture(demoModel(), atlas, 3);
  EXPECT_EQ(three.samples, 9 * one.samples);
  EXPECT_EQ(three.owner, one.owner);
  std::size_t checked = 0;
  for (int y = 0; y < 64; y += 3)
    for (int x = 0; x < 64; x += 3) {
      const int t = three.owner[std::size_t(y) * 64 + x];
      if (t < 0) continue;
      const glm::uvec3 tri = atlas.mesh.triangles[t];
      const glm::vec2 a = atlas.mesh.uvs[tri.x] * 64.0f, b = atlas.mesh.uvs[tri.y] * 64.0f,
                      c = atlas.mesh.uvs[tri.z] * 64.0f;
      glm::vec3 mean(0.0f);
      for (int sy = 0; sy < 3; ++sy)
        for (int sx = 0; sx < 3; ++sx) {
          const glm::vec2 q(x + (sx + 0.5f) / 3, y + (sy + 0.5f) / 3);
          const float area = triangleArea2(a, b, c);
          const glm::vec3 w(triangleArea2(b, c, q) / area, triangleArea2(c, a, q) / area,
                            triangleArea2(a, b, q) / area);
          mean += demoModel()
                      .evaluate(w.x * atlas.mesh.positions[tri.x] + w.y * atlas.mesh.positions[tri.y] +
                                w.z * atlas.mesh.positions[tri.z])
                      .color;
        }
      const float* texel = three.image.pixel(x, y);
      EXPECT_LT(maxDifference(glm::vec3(texel[0], texel[1], texel[2]), mean / 9.0f), 1e-4f);
      ++checked;
    }
  EXPECT_GT(checked, 100u);
}

TEST(PartBake, GutterIsFilledSoMipmapsDoNotBleedBlack) {
  const fs::path dir = folder("gutter");
  UvAtlasOptions options;
  options.resolution = 128;
  const UvAtlas atlas = buildUvAtlas(placedBox(dir), options);
  const BakedTexture baked = bakePartTexture(demoModel(), atlas);
  // Every gutter texel holds wood colour: none left black, and on average the gutter looks like the part
  // (a mip level that averages across a chart's rim shows no dark seam).
  glm::dvec3 part(0.0), gutter(0.0);
  std::size_t partCount = 0, gutterCount = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const float* p = baked.image.pixel(x, y);
      const glm::dvec3 c(p[0], p[1], p[2]);
      if (baked.owner[std::size_t(y) * 128 + x] >= 0) {
        part += c, ++partCount;
      } else {
        EXPECT_GT(p[0] + p[1] + p[2], 0.0f) << "gutter texel " << x << "," << y << " left black";
        gutter += c, ++gutterCount;
      }
    }
  ASSERT_GT(gutterCount, 0u);
  EXPECT_LT(glm::length(part / double(partCount) - gutter / double(gutterCount)), 0.1);
}

TEST(PartBake, CancelStopsTheBake) {
  const fs::path dir = folder("cancel");
  const UvAtlas atlas = buildUvAtlas(placedBox(dir));
  std::stop_source stop;
  stop.request_stop();
  EXPECT_THROW(bakePartTexture(demoModel(), atlas, 1, Progress{nullptr, stop.get_token()}), Cancelled);
}

TEST(PartExport, ObjMtlPngReadBackWithAssimpAndOpenImageIO) {
  const fs::path dir = folder("obj");
  PartExportOptions options;
  options.mesh = kerf::testing::writePrismPly(dir / "prism.ply", 9, 24, 24);
  options.placement.rotationDeg = {30, 0, 0};
  options.textureResolution = 256;
  options.samples = 2;
  const PartExportResult result = exportPart(demoModel(), options, dir / "part.obj");
  ASSERT_EQ(result.files.size(), 3u);
  EXPECT_EQ(result.files[1], dir / "part.mtl");
  EXPECT_EQ(result.files[2], dir / "part.png");
  EXPECT_TRUE(result.fit.fits());

  // What the export should have written, rebuilt from the same steps.
  const Mesh placed = placeMesh(loadMesh(options.mesh), options.placement);
  UvAtlasOptions atlasOptions;
  atlasOptions.resolution = 256;
  const UvAtlas atlas = buildUvAtlas(placed, atlasOptions);
  const BakedTexture baked = bakePartTexture(demoModel(), atlas, 2);
  EXPECT_EQ(result.samples, baked.samples);

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "part.obj").string(), 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_EQ(scene->mNumMeshes, 1u);
  const aiMesh& mesh = *scene->mMeshes[0];
  ASSERT_EQ(mesh.mNumFaces, atlas.mesh.triangles.size());
  ASSERT_TRUE(mesh.HasNormals());
  ASSERT_TRUE(mesh.HasTextureCoords(0));
  for (unsigned f = 0; f < mesh.mNumFaces; ++f)
    for (int k = 0; k < 3; ++k) {
      const unsigned i = mesh.mFaces[f].mIndices[k], j = atlas.mesh.triangles[f][k];
      EXPECT_EQ(glm::vec3(mesh.mVertices[i].x, mesh.mVertices[i].y, mesh.mVertices[i].z),
                atlas.mesh.positions[j]);
      EXPECT_EQ(glm::vec3(mesh.mNormals[i].x, mesh.mNormals[i].y, mesh.mNormals[i].z), atlas.mesh.normals[j]);
      // OBJ's v is up.
      EXPECT_NEAR(mesh.mTextureCoords[0][i].x, atlas.mesh.uvs[j].x, 1e-6f);
      EXPECT_NEAR(mesh.mTextureCoords[0][i].y, 1.0f - atlas.mesh.uvs[j].y, 1e-6f);
    }
  aiString texture;
  ASSERT_EQ(scene->mMaterials[mesh.mMaterialIndex]->GetTexture(aiTextureType_DIFFUSE, 0, &texture),
            AI_SUCCESS);
  EXPECT_STREQ(texture.C_Str(), "part.png");

  const Image png = readImage(dir / "part.png");
  ASSERT_EQ(png.width, 256);
  const ImageDifference d = compareImages(png, baked.image, 0.6f / 255.0f);
  EXPECT_EQ(d.shareOverTolerance, 0.0);
}

TEST(PartExport, GlbReadBackWithTinyGltf) {
  const fs::path dir = folder("glb");
  PartExportOptions options;
  options.mesh = kerf::testing::writeBoxObj(dir / "box.obj", {20, 12, 28});
  options.placement.rotationDeg = {0, 25, 10};
  options.placement.translationMm = {1, -2, 0};
  options.textureResolution = 128;
  const PartExportResult result = exportPart(demoModel(), options, dir / "part.glb");
  ASSERT_EQ(result.files.size(), 1u);
  const UvAtlas atlas = [&] {
    UvAtlasOptions o;
    o.resolution = 128;
    return buildUvAtlas(placedBox(dir), o);
  }();
  const BakedTexture baked = bakePartTexture(demoModel(), atlas, options.samples);

  std::ifstream file(dir / "part.glb", std::ios::binary);
  char magic[4];
  file.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), "glTF");

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, (dir / "part.glb").string())) << error;
  EXPECT_EQ(model.asset.version, "2.0");
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.nodes.size(), 1u);
  EXPECT_EQ(model.nodes[0].scale, (std::vector<double>{0.001, 0.001, 0.001}));
  const tinygltf::Primitive& primitive = model.meshes[0].primitives.at(0);
  const auto read = [&](int accessorIndex, auto element) {
    using T = decltype(element);
    const tinygltf::Accessor& a = model.accessors.at(accessorIndex);
    const tinygltf::BufferView& v = model.bufferViews.at(a.bufferView);
    std::vector<T> out(a.count);
    std::memcpy(out.data(), model.buffers.at(v.buffer).data.data() + v.byteOffset + a.byteOffset,
                a.count * sizeof(T));
    return out;
  };
  EXPECT_EQ(read(primitive.attributes.at("POSITION"), glm::vec3()), atlas.mesh.positions);
  EXPECT_EQ(read(primitive.attributes.at("NORMAL"), glm::vec3()), atlas.mesh.normals);
  EXPECT_EQ(read(primitive.attributes.at("TEXCOORD_0"), glm::vec2()), atlas.mesh.uvs);
  const std::vector<unsigned> indices = read(primitive.indices, 0u);
  ASSERT_EQ(indices.size(), atlas.mesh.triangles.size() * 3);
  EXPECT_EQ(std::memcmp(indices.data(), atlas.mesh.triangles.data(), indices.size() * sizeof(unsigned)), 0);
  const tinygltf::Accessor& positions = model.accessors.at(primitive.attributes.at("POSITION"));
  const MeshBounds bounds = meshBounds(atlas.mesh.positions);
  EXPECT_NEAR(positions.minValues.at(0), bounds.min.x, 1e-5);
  EXPECT_NEAR(positions.maxValues.at(2), bounds.max.z, 1e-5);

  // The material's base colour is the embedded PNG, decoded by tinygltf: the bake in 8 bits.
  const tinygltf::Material& material = model.materials.at(primitive.material);
  const tinygltf::Texture& texture = model.textures.at(material.pbrMetallicRoughness.baseColorTexture.index);
  const tinygltf::Image& image = model.images.at(texture.source);
  EXPECT_EQ(image.mimeType, "image/png");
  ASSERT_EQ(image.width, 128);
  ASSERT_EQ(image.height, 128);
  ASSERT_GE(image.component, 3);
  float worst = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x)
      for (int c = 0; c < 3; ++c)
        worst =
            std::max(worst, std::abs(image.image[(std::size_t(y) * 128 + x) * image.component + c] / 255.0f -
                                     baked.image.pixel(x, y)[c]));
  EXPECT_LT(worst, 0.6f / 255.0f);

  // A second reader: assimp's glTF 2 importer takes the file, with the node's mm-to-m scale.
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "part.glb").string(), 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_EQ(scene->mNumMeshes, 1u);
  EXPECT_EQ(scene->mMeshes[0]->mNumFaces, atlas.mesh.triangles.size());
  EXPECT_EQ(scene->mMeshes[0]->mNumVertices, atlas.mesh.positions.size());
  // The single node becomes assimp's root, holding the mesh and the scale.
  EXPECT_EQ(scene->mRootNode->mNumMeshes, 1u);
  EXPECT_NEAR(scene->mRootNode->mTransformation.a1, 0.001f, 1e-7f);
  EXPECT_NEAR(scene->mRootNode->mTransformation.c3, 0.001f, 1e-7f);
}

TEST(PartExport, DoesNotFitWarnsOrFailsAndErrorsNameTheFile) {
  const fs::path dir = folder("errors");
  ExportRequest request;
  request.out = dir / "part.glb";
  request.part.mesh = kerf::testing::writeBoxObj(dir / "big.obj", {30, 30, 30});
  request.part.placement.translationMm = {10, 0, 0};  // x from -5 to 25 in a 40 mm block: 5 mm beyond E
  request.part.textureResolution = 64;
  ExportSummary summary = runExport(demoModel(), request);
  EXPECT_EQ(summary.kind, ExportKind::Part);
  EXPECT_NE(summary.warning.find("sticks out of the block by 5.0 mm at face E (+x)"), std::string::npos)
      << summary.warning;
  EXPECT_TRUE(fs::exists(request.out));
  EXPECT_GT(summary.samples, 0u);

  const auto errorOf = [&](ExportRequest r) -> std::string {
    try {
      runExport(demoModel(), r);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  };
  ExportRequest strict = request;
  strict.out = dir / "strict.glb";
  strict.part.requireFit = true;
  EXPECT_NE(errorOf(strict).find("big.obj: the part sticks out of the block by 5.0 mm at face E (+x)"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(strict.out));

  ExportRequest noMesh = request;
  noMesh.part.mesh.clear();
  EXPECT_NE(errorOf(noMesh).find("needs a mesh: --mesh FILE"), std::string::npos);
  ExportRequest missing = request;
  missing.part.mesh = dir / "nope.stl";
  EXPECT_NE(errorOf(missing).find("nope.stl: no such file"), std::string::npos);
  ExportRequest nan = request;
  nan.part.placement.rotationDeg.x = std::nanf("");
  EXPECT_NE(errorOf(nan).find("rotation must be three numbers"), std::string::npos);
  ExportRequest open = request;  // a box without its top: baked, with a warning
  open.out = dir / "tray.glb";
  open.part.mesh = kerf::testing::writeBoxesObj(dir / "tray.obj", {{{-5, -5, -5}, {5, 5, 5}}}, 1);
  open.part.placement.translationMm = {0, 0, 0};
  summary = runExport(demoModel(), open);
  EXPECT_TRUE(fs::exists(open.out));
  EXPECT_NE(summary.warning.find("the mesh is not a closed solid: 4 open edges"), std::string::npos)
      << summary.warning;
  ExportRequest noFolder = request;
  noFolder.out = dir / "no-such-folder" / "x.obj";
  EXPECT_NE(errorOf(noFolder).find("folder"), std::string::npos);
}
