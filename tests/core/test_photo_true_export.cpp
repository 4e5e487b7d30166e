// Exports of a photo-true project (issue 17, docs/export.md): the demo block rendered by Kerf's own model
// stands in for the photos (as in test_photo_true.cpp), written as the project's face photos. An exported
// face or cut is the appearance's own surface (and not the procedural model's); a textured part's texels
// come from the photos and never from a held-out face's (colour volumes: test_photo_true_volume.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <opencv2/imgproc.hpp>

#include "appearance/photo_true_appearance.hpp"
#include "appearance/photo_true_source.hpp"
#include "appearance/surface_grid.hpp"
#include "appearance/texel_guidance.hpp"
#include "demo/demo_block.hpp"
#include "export/export_job.hpp"
#include "export/photo_true_part_bake.hpp"
#include "io/image.hpp"
#include "io/png_codec.hpp"
#include "io/project.hpp"
#include "mesh/bake_part_texture.hpp"
#include "mesh/mesh_loader.hpp"
#include "mesh/uv_atlas.hpp"
#include "part_meshes.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "test_files.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

constexpr int kSide = 64;  // photo pixels per face of the 40 mm demo cube: 1.6 px/mm

// The demo project with its six faces rendered by the model as its photos, in the photo-true appearance.
struct PhotoProject {
  Project project = demoProject(7);
  std::unique_ptr<WoodModel> model;
  fs::path dir;
  explicit PhotoProject(const std::string& name, const char* heldOut = "") {
    dir = kerf::testing::scratchFolder("photo-true-export", name);
    model = std::make_unique<WoodModel>(project);
    for (FaceId face : kAllFaces) {
      const fs::path file = dir / (std::string(1, faceLetter(face)) + "_col.png");
      writeImage(file, renderFace(*model, face, {kSide, kSide}, 2));
      project.facePhotos[faceIndex(face)] = file;
    }
    project.appearance = Appearance::Photo;
    project.heldOutFaces = parseFaceSet(heldOut);
  }
  // The appearance as every command makes it (the same photos, options and seed).
  PhotoTrueAppearance appearance() const {
    return PhotoTrueAppearance(*model, loadAppearancePhotos(project), project.heldOutFaces,
                               photoTrueOptionsFor(*model));
  }
  ExportRequest request(const fs::path& out) const {
    ExportRequest r;
    r.out = out;
    r.pxPerMm = kSide / 40.0f;
    r.photoTrue = photoTrueSourceOf(project);
    return r;
  }
};

float maxDifference(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.channels, b.channels);
  float worst = 0;
  for (std::size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
    worst = std::max(worst, std::abs(a.pixels[i] - b.pixels[i]));
  return worst;
}

float meanDifference(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(a.pixels[i] - b.pixels[i]);
  return float(sum / a.pixels.size());
}

// A 30 mm cube in the middle of the 40 mm block (six charts, one per side) and its atlas.
struct CubePart {
  Mesh mesh;
  UvAtlas atlas;
  CubePart(const fs::path& dir, int resolution) {
    mesh = loadMesh(kerf::testing::writeBoxObj(dir / "cube.obj", {30, 30, 30}));
    UvAtlasOptions options;
    options.resolution = resolution;
    atlas = buildUvAtlas(mesh, options);
  }
};

}  // namespace

TEST(PhotoTrueExport, FaceAndCutImagesAreTheAppearancesOwn) {
  const PhotoProject p("images");
  const PhotoTrueAppearance appearance = p.appearance();
  ExportRequest faceRequest = p.request(p.dir / "face_c.png");
  faceRequest.face = FaceId::C;
  const ExportSummary face = runExport(*p.model, faceRequest);
  EXPECT_NE(face.message.find("photo-true"), std::string::npos) << face.message;
  bool saysPhotoTrue = false;  // the file says whose colours it holds
  for (const PngText& text : readPngInfo(p.dir / "face_c.png").text)
    saysPhotoTrue = saysPhotoTrue || (text.key == "Kerf:appearance" && text.value == "photo-true");
  EXPECT_TRUE(saysPhotoTrue);
  const Image written = readImage(p.dir / "face_c.png");
  const Image expected = appearance.renderFace(FaceId::C, {kSide, kSide});
  EXPECT_LE(maxDifference(written, expected), 0.5f / 255 + 1e-4f);  // 8-bit PNG
  const Image procedural = renderFace(*p.model, FaceId::C, {kSide, kSide}, 2);
  EXPECT_GT(meanDifference(written, procedural), 0.02f);

  ExportRequest cut = p.request(p.dir / "cut.png");
  cut.plane = CutPlane({0, 0, 0}, glm::normalize(glm::vec3(1, 0.6f, 0.3f)));
  runExport(*p.model, cut);
  const Image writtenCut = readImage(p.dir / "cut.png", true);
  const Image expectedCut = appearance.renderCut(*cut.plane, cut.pxPerMm);
  ASSERT_EQ(writtenCut.channels, 4);  // transparent outside the block
  EXPECT_LE(maxDifference(writtenCut, expectedCut), 0.5f / 255 + 1e-4f);

  // Without the source (a procedural project) the export is the model's, as before.
  ExportRequest plain = p.request(p.dir / "face_c_procedural.png");
  plain.photoTrue.reset();
  plain.face = FaceId::C;
  runExport(*p.model, plain);
  EXPECT_LE(maxDifference(readImage(p.dir / "face_c_procedural.png"),
                          renderFaceLayers(*p.model, FaceId::C, plain.pxPerMm, 2).colour),
            0.5f / 255 + 1e-4f);
}

TEST(PhotoTrueExport, DepthStackStartsAtTheFaceAndStaysPhotoTrue) {
  const PhotoProject p("depth");
  ExportRequest r = p.request(p.dir / "stack");
  r.depthStack = parseDepthStack("A,2,2");
  runExport(*p.model, r);
  const Image top = readImage(p.dir / "stack" / "A_000.png"),
              deeper = readImage(p.dir / "stack" / "A_001.png");
  EXPECT_LE(maxDifference(top, p.appearance().renderFace(FaceId::A, {kSide, kSide})), 0.5f / 255 + 1e-4f);
  const LayeredImage procedural = renderFaceAtDepth(*p.model, FaceId::A, 2.0f, r.pxPerMm, 2);
  EXPECT_GT(meanDifference(deeper, procedural.colour), 0.02f);
}

TEST(PhotoTrueExport, PartTexelsComeFromThePhotosAndNeverFromHeldOutFaces) {
  // Every photo recoloured to magenta greys (no green at all), the held-out face D's pure green: a texel
  // with green in it came from the procedural model or from D.
  PhotoProject p("part-palette", "D");
  for (FaceId face : kAllFaces) {
    const fs::path file = p.project.facePhotos[faceIndex(face)];
    Image photo = readImage(file);
    for (std::size_t i = 0; i < photo.pixels.size(); i += 3) {
      const float lum =
          0.299f * photo.pixels[i] + 0.587f * photo.pixels[i + 1] + 0.114f * photo.pixels[i + 2];
      const bool held = face == FaceId::D;
      photo.pixels[i] = held ? 0.0f : lum;
      photo.pixels[i + 1] = held ? 1.0f : 0.0f;
      photo.pixels[i + 2] = held ? 0.0f : lum;
    }
    writeImage(file, photo);
  }
  const CubePart part(p.dir, 96);
  const Mesh& cube = part.mesh;
  const UvAtlas& atlas = part.atlas;
  const BakedTexture baked = bakePhotoTruePart(p.appearance(), *p.model, cube, atlas, 2);
  double red = 0;
  float green = 0;
  int texels = 0;
  for (int i = 0; i < atlas.resolution * atlas.resolution; ++i) {
    if (baked.owner[i] < 0) continue;
    red += baked.image.pixels[i * 3];
    green = std::max(green, baked.image.pixels[i * 3 + 1]);
    ++texels;
  }
  EXPECT_GT(texels, atlas.resolution * atlas.resolution / 4);
  EXPECT_LT(green, 1e-4f);
  EXPECT_GT(red / texels, 0.1);
  // The check sees green: the procedural bake of the same part has it in every texel.
  const BakedTexture procedural = bakePartTexture(*p.model, atlas, 1);
  int greenTexels = 0;
  for (int i = 0; i < atlas.resolution * atlas.resolution; ++i)
    greenTexels += procedural.owner[i] >= 0 && procedural.image.pixels[i * 3 + 1] > 0.05f ? 1 : 0;
  EXPECT_EQ(greenTexels, texels);
}

TEST(PhotoTrueExport, PartTextureFollowsTheFieldOnEveryChart) {
  // With the model's own renders as photos, the photo-true texture of a cube inside the block resembles
  // the procedural bake of the same cube (its truth) chart by chart: the rings land where the field puts
  // them through each texel's point and frame. A chart compared with its truth turned by 90 degrees
  // (same wood, wrong place) scores clearly less.
  const PhotoProject p("part-field");
  const CubePart part(p.dir, 128);
  const Mesh& cube = part.mesh;
  const UvAtlas& atlas = part.atlas;
  const BakedTexture photoTrue = bakePhotoTruePart(p.appearance(), *p.model, cube, atlas, 2);
  const BakedTexture truth = bakePartTexture(*p.model, atlas, 2);
  auto luminance = [](const Image& image, const cv::Rect& r) {
    cv::Mat out(r.height, r.width, CV_32F);
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) {
        const float* c = image.pixel(r.x + x, r.y + y);
        out.at<float>(y, x) = 0.299f * c[0] + 0.587f * c[1] + 0.114f * c[2];
      }
    cv::GaussianBlur(out, out, cv::Size(0, 0), 1.0);
    return out;
  };
  auto correlation = [](const cv::Mat& a, const cv::Mat& b) {
    const cv::Mat x = a - cv::mean(a)[0], y = b - cv::mean(b)[0];
    return x.dot(y) / std::sqrt(x.dot(x) * y.dot(y) + 1e-12);
  };
  ASSERT_EQ(atlas.charts.size(), 6u);
  double sum = 0, turnedSum = 0;
  for (const UvAtlas::Chart& c : atlas.charts) {
    const int inset = atlas.padding + 4;
    const int side = std::min(c.width, c.height) - 2 * inset;
    const cv::Rect inner(c.x + inset, c.y + inset, side, side);
    const cv::Mat a = luminance(photoTrue.image, inner), b = luminance(truth.image, inner);
    cv::Mat turned;
    cv::rotate(b, turned, cv::ROTATE_90_CLOCKWISE);
    const double corr = correlation(a, b), unrelated = correlation(a, turned);
    std::printf("chart axis %d: corr %.3f (turned truth %.3f)\n", c.axis, corr, unrelated);
    EXPECT_GT(corr, 0.45);
    sum += corr;
    turnedSum += unrelated;
  }
  EXPECT_GT(sum / 6, turnedSum / 6 + 0.4);
}

TEST(PhotoTrueExport, PartExportReportsProgressAndCancels) {
  const PhotoProject p("part-progress");
  ExportRequest r = p.request(p.dir / "cube.glb");
  r.part.mesh = p.dir / "cube.obj";
  kerf::testing::writeBoxObj(r.part.mesh, {30, 30, 30});
  r.part.textureResolution = 64;
  std::atomic<double> highest{0.0};
  Progress progress;
  progress.report = [&](double f) {
    double seen = highest.load();
    while (f > seen && !highest.compare_exchange_weak(seen, f)) {
    }
  };
  const ExportSummary summary = runExport(*p.model, r, progress);
  EXPECT_NE(summary.message.find("in the photo-true appearance"), std::string::npos) << summary.message;
  EXPECT_GE(highest.load(), 1.0);
  std::stop_source stop;
  stop.request_stop();
  r.out = p.dir / "cancelled.glb";
  EXPECT_THROW(runExport(*p.model, r, {nullptr, stop.get_token()}), Cancelled);
  EXPECT_FALSE(fs::exists(r.out));
}

TEST(PhotoTrueExport, MissingPhotoIsAnErrorNamingTheFile) {
  PhotoProject p("missing");
  fs::remove(p.project.facePhotos[2]);
  ExportRequest r = p.request(p.dir / "face_a.png");
  r.face = FaceId::A;
  try {
    runExport(*p.model, r);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("C_col.png"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(p.dir / "face_a.png"));
  // A PNG of the growth layer shows no colour: the photos are not read.
  r.image.pngLayer = ImageLayer::Growth;
  EXPECT_NO_THROW(runExport(*p.model, r));
}

TEST(PhotoTrueExport, TexelGuidanceOfAFaceIsTheFacesGuidance) {
  // The texels of a face given one by one (points and frames of its grid) have the face's features: the
  // same phase, sawing, density and sapwood, the same grain direction inside (the averaging differs only
  // at the border).
  const Project project = demoProject(7);
  const WoodModel model(project);
  for (FaceId face : {FaceId::B, FaceId::C}) {  // end grain, side grain
    const SurfaceGrid grid = faceGrid(project.block, face, {40, 40});
    TexelSurface texels;
    texels.width = texels.height = 40;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        texels.point.push_back(grid.point(float(x), float(y)));
        texels.right.push_back(grid.right);
        texels.down.push_back(grid.down);
        texels.region.push_back(0);
      }
    const SurfaceGuidance a = computeGuidance(model, grid, {}), b = computeTexelGuidance(model, texels, {});
    int turned = 0;
    for (int y = 10; y < 30; ++y)
      for (int x = 10; x < 30; ++x) {
        for (int c : {0, 1, 2, 5}) EXPECT_NEAR(a.at(x, y)[c], b.at(x, y)[c], 1e-3f) << "channel " << c;
        // The growth gradient's finite differences differ (the grid's neighbours a pixel apart, here half a
        // texel each way in 3D): what depends on it agrees within a few percent of the weights.
        for (int c : {3, 4, 7, 8}) EXPECT_NEAR(a.at(x, y)[c], b.at(x, y)[c], 0.25f) << "channel " << c;
        const float d =
            std::remainder(a.grainAngle[y * 40 + x] - b.grainAngle[y * 40 + x], 2.0f * 3.14159265f);
        turned += std::abs(d) > 0.15f ? 1 : 0;
      }
    EXPECT_LT(turned, 20) << "face " << faceLetter(face);  // of 400
  }
}

TEST(PhotoTrueExport, PartTextureIsTheSameWhateverTheThreads) {
  const PhotoProject p("part-threads");
  const CubePart part(p.dir, 64);
  const Mesh& cube = part.mesh;
  const UvAtlas& atlas = part.atlas;
  const PhotoTrueAppearance appearance = p.appearance();
  const int threads = workerThreads();
  setWorkerThreads(1);
  const BakedTexture one = bakePhotoTruePart(appearance, *p.model, cube, atlas, 1);
  setWorkerThreads(2);
  const BakedTexture two = bakePhotoTruePart(appearance, *p.model, cube, atlas, 1);
  setWorkerThreads(threads);
  EXPECT_EQ(one.image.pixels, two.image.pixels);
}
