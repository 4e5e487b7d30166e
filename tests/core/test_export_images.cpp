// Image export (core/export/image_export.hpp): PNG, 16-bit TIFF pages and EXR channels read back with
// OpenImageIO and compared with the renderers and the growth field; the scale stored in the files.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "test_files.hpp"

#include <cmath>

#include "demo/demo_block.hpp"
#include "export/export_job.hpp"
#include "export/image_export.hpp"
#include "render/renderers.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

fs::path artifact(const std::string& name) {
  return kerf::testing::artifactFile("export", name);
}

const WoodModel& demoModel() {
  static const Project project = demoProject();
  static const WoodModel model(project);
  return model;
}

// One subimage of a file, all channels as float, with its spec.
struct ReadBack {
  OIIO::ImageSpec spec;
  std::vector<float> pixels;
  float at(int x, int y, int c) const {
    return pixels[(static_cast<std::size_t>(y) * spec.width + x) * spec.nchannels + c];
  }
};
ReadBack readBack(const fs::path& path, int subimage = 0) {
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << OIIO::geterror();
  ReadBack r;
  if (!in || !in->seek_subimage(subimage, 0)) return r;
  r.spec = in->spec();
  r.pixels.resize(static_cast<std::size_t>(r.spec.width) * r.spec.height * r.spec.nchannels);
  EXPECT_TRUE(in->read_image(subimage, 0, 0, r.spec.nchannels, OIIO::TypeDesc::FLOAT, r.pixels.data()));
  return r;
}

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

void expectDpi(const OIIO::ImageSpec& spec, float pxPerMm) {
  const std::string unit = spec.get_string_attribute("ResolutionUnit");
  EXPECT_TRUE(unit == "in" || unit == "inch") << unit;
  EXPECT_NEAR(spec.get_float_attribute("XResolution"), pxPerMm * 25.4f, 0.01f);
  EXPECT_NEAR(spec.get_float_attribute("YResolution"), pxPerMm * 25.4f, 0.01f);
}

}  // namespace

TEST(ExportImage, FacePngMatchesTheRendererAndStoresItsScale) {
  const WoodModel& model = demoModel();
  const float pxPerMm = 3.0f;
  const LayeredImage image = renderFaceLayers(model, FaceId::C, pxPerMm, 2);
  const fs::path path = artifact("face_c.png");
  writeLayeredImage(path, image);

  const Image reference = renderFace(model, FaceId::C, model.block().faceImageSize(FaceId::C, pxPerMm), 2);
  const ReadBack r = readBack(path);
  ASSERT_EQ(r.spec.width, reference.width);
  ASSERT_EQ(r.spec.height, reference.height);
  ASSERT_EQ(r.spec.nchannels, 3);
  EXPECT_EQ(r.spec.format, OIIO::TypeDesc::UINT8);
  float worst = 0;
  for (std::size_t i = 0; i < r.pixels.size(); ++i)
    worst = std::max(worst, std::abs(r.pixels[i] - reference.pixels[i]));
  EXPECT_LE(worst, 0.5f / 255.0f + 1e-5f);  // 8-bit rounding only
  expectDpi(r.spec, pxPerMm);
  EXPECT_NEAR(std::stof(r.spec.get_string_attribute("Kerf:mm_per_pixel")), 1.0f / pxPerMm, 1e-6f);

  const ExportedImageInfo info = readExportedImageInfo(path);
  EXPECT_NEAR(info.dotsPerInch, 76.2f, 0.01f);
  EXPECT_NEAR(info.mmPerPixel, 1.0f / 3.0f, 1e-6f);
  EXPECT_EQ(info.subimages, 1);
}

TEST(ExportImage, GrowthPngDecodesToTheFieldThroughItsStoredRange) {
  const WoodModel& model = demoModel();
  const LayeredImage image = renderFaceLayers(model, FaceId::B, 2.0f, 1);
  const fs::path path = artifact("face_b_growth.png");
  ImageWriteOptions options;
  options.pngLayer = ImageLayer::Growth;
  writeLayeredImage(path, image, options);

  const ReadBack r = readBack(path);
  ASSERT_EQ(r.spec.nchannels, 1);
  EXPECT_EQ(r.spec.format, OIIO::TypeDesc::UINT16);
  float lo = 0, hi = 0;
  ASSERT_EQ(std::sscanf(r.spec.get_string_attribute("Kerf:growth_range").c_str(), "%f %f", &lo, &hi), 2);
  ASSERT_GT(hi, lo);
  const glm::ivec2 size(r.spec.width, r.spec.height);
  for (glm::ivec2 p :
       {glm::ivec2(0, 0), glm::ivec2(size.x - 1, size.y / 2), glm::ivec2(size.x / 3, size.y - 1)}) {
    const float years = lo + r.at(p.x, p.y, 0) * (hi - lo);
    EXPECT_NEAR(years, model.material().year(model.block().pixelCenter(FaceId::B, p.x, p.y, size)),
                (hi - lo) / 65535.0f + 1e-4f);
  }
}

TEST(ExportImage, TiffHasSixteenBitColourAndGrowthAndRingPages) {
  const WoodModel& model = demoModel();
  const float pxPerMm = 2.5f;
  const LayeredImage image = renderFaceLayers(model, FaceId::A, pxPerMm, 1);
  const fs::path path = artifact("face_a.tif");
  writeLayeredImage(path, image);

  const ReadBack colour = readBack(path, 0), growth = readBack(path, 1), rings = readBack(path, 2);
  EXPECT_EQ(colour.spec.format, OIIO::TypeDesc::UINT16);
  EXPECT_EQ(growth.spec.format, OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(rings.spec.format, OIIO::TypeDesc::UINT16);
  for (const ReadBack* page : {&colour, &growth, &rings}) {
    ASSERT_EQ(page->spec.width, image.colour.width);
    expectDpi(page->spec, pxPerMm);
  }
  const Image reference = renderFace(model, FaceId::A, glm::ivec2(colour.spec.width, colour.spec.height), 1);
  float worst = 0;
  for (std::size_t i = 0; i < colour.pixels.size(); ++i)
    worst = std::max(worst, std::abs(colour.pixels[i] - reference.pixels[i]));
  EXPECT_LE(worst, 0.5f / 65535.0f + 1e-6f);
  const glm::ivec2 size(growth.spec.width, growth.spec.height);
  for (int y = 0; y < size.y; y += 7)
    for (int x = 0; x < size.x; x += 5) {
      ASSERT_FLOAT_EQ(growth.at(x, y, 0),
                      model.material().year(model.block().pixelCenter(FaceId::A, x, y, size)));
      ASSERT_NEAR(rings.at(x, y, 0), image.rings.pixel(x, y)[0], 0.5f / 65535.0f + 1e-6f);
    }
  EXPECT_EQ(readExportedImageInfo(path).subimages, 3);

  ImageWriteOptions colourOnly;
  colourOnly.extraLayers = false;
  writeLayeredImage(artifact("face_a_colour_only.tif"), image, colourOnly);
  EXPECT_EQ(readExportedImageInfo(artifact("face_a_colour_only.tif")).subimages, 1);
}

TEST(ExportImage, ExrCutHasLinearColourAlphaGrowthAndRingChannels) {
  const WoodModel& model = demoModel();
  const CutPlane plane({0, 0, 0}, {1, 1, 1});
  const float pxPerMm = 2.0f;
  const LayeredImage image = renderCutLayers(model, plane, pxPerMm, 1);
  const Image reference = renderCut(model, plane, pxPerMm, 1);
  for (bool half : {true, false}) {
    const fs::path path = artifact(half ? "cut_half.exr" : "cut_float.exr");
    ImageWriteOptions options;
    options.exrHalf = half;
    writeLayeredImage(path, image, options);
    const ReadBack r = readBack(path);
    ASSERT_EQ(r.spec.nchannels, 6);
    const auto channel = [&](const std::string& name) {
      const int c = r.spec.channelindex(name);
      EXPECT_GE(c, 0) << name;
      return c;
    };
    const int R = channel("R"), A = channel("A"), growth = channel("growth"), rings = channel("rings");
    EXPECT_EQ(r.spec.channelformat(R), half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(r.spec.channelformat(growth), OIIO::TypeDesc::FLOAT);
    EXPECT_NEAR(r.spec.get_float_attribute("Kerf:mm_per_pixel"), 0.5f, 1e-6f);
    EXPECT_FLOAT_EQ(r.spec.get_float_attribute("PixelAspectRatio"), 1.0f);
    expectDpi(r.spec, pxPerMm);
    int inside = 0, outside = 0;
    for (int y = 0; y < r.spec.height; ++y)
      for (int x = 0; x < r.spec.width; ++x) {
        const float* ref = reference.pixel(x, y);
        ASSERT_NEAR(r.at(x, y, A), ref[3], 1e-3f);
        if (ref[3] == 0.0f) {
          ++outside;
          ASSERT_EQ(r.at(x, y, growth), 0.0f);
          continue;
        }
        ++inside;
        ASSERT_NEAR(r.at(x, y, R), srgbToLinear(ref[0]) * ref[3], half ? 2e-3f : 1e-6f);  // premultiplied
        ASSERT_FLOAT_EQ(r.at(x, y, growth), image.growth.pixel(x, y)[0]);
        ASSERT_NEAR(r.at(x, y, rings), image.rings.pixel(x, y)[0], half ? 1e-3f : 0.0f);
      }
    EXPECT_GT(inside, 100);
    EXPECT_GT(outside, 100);  // a diagonal cut leaves corners outside the block
  }
}

TEST(ExportImage, RingLinesLieOnTheRingLevels) {
  const WoodModel& model = demoModel();
  const LayeredImage image = renderFaceLayers(model, FaceId::A, 8.0f, 1);
  const float offset = model.params().ringOffset;
  int onLine = 0;
  for (std::size_t i = 0; i < image.growth.pixels.size(); ++i) {
    const float t = image.growth.pixels[i] - offset;
    const float years = std::abs(t - std::round(t));  // distance to the nearest ring, in years
    const float ring = image.rings.pixels[i];
    if (ring >= 0.99f) {
      ++onLine;
      ASSERT_LT(years, 0.2f);
    }
    if (years > 0.45f) {
      ASSERT_EQ(ring, 0.0f);
    }
  }
  const double share = double(onLine) / image.growth.pixels.size();
  EXPECT_GT(share, 0.01);  // rings are there, and thin
  EXPECT_LT(share, 0.25);
}

TEST(ExportImage, ErrorsLeaveNoFileBehind) {
  const LayeredImage image = renderFaceLayers(demoModel(), FaceId::A, 0.5f, 1);
  EXPECT_THROW(writeLayeredImage(artifact("no-such-folder") / "x.png", image), InputError);
  EXPECT_FALSE(fs::exists(artifact("no-such-folder")));
  EXPECT_THROW(writeLayeredImage(artifact("face.jpg"), image), InputError);
  EXPECT_FALSE(fs::exists(artifact("face.jpg")));
  // A successful export leaves its file and nothing else (no temporary file).
  const fs::path folder = artifact("clean");
  fs::remove_all(folder);
  fs::create_directories(folder);
  writeLayeredImage(folder / "face.exr", image);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"face.exr"});
}

TEST(ExportJob, PicksTheKindFromTheExtension) {
  ExportRequest request;
  request.face = FaceId::A;
  for (const char* name : {"a.png", "a.TIF", "a.tiff", "a.exr"}) {
    request.out = name;
    EXPECT_EQ(exportKindOf(request), ExportKind::Image) << name;
  }
  request.out = "v.nrrd";
  EXPECT_EQ(exportKindOf(request), ExportKind::Volume);
  request.out = "v.vdb";
  EXPECT_EQ(exportKindOf(request), ExportKind::Volume);
  request.out = "part.glb";
  EXPECT_EQ(exportKindOf(request), ExportKind::Part);
  try {
    runExport(demoModel(), request);
    FAIL() << "a part export without a mesh should fail";
  } catch (const InputError& e) {  // parts themselves: test_part_export.cpp
    EXPECT_NE(std::string(e.what()).find("needs a mesh: --mesh FILE"), std::string::npos) << e.what();
  }
  request.out = "a.xyz";
  EXPECT_THROW(exportKindOf(request), InputError);
  request.out = "a.png";
  request.plane = CutPlane({0, 0, 0}, {0, 0, 1});
  EXPECT_THROW(exportKindOf(request), InputError);  // both a face and a plane
  request.face.reset();
  request.plane.reset();
  EXPECT_THROW(exportKindOf(request), InputError);  // neither
  request.depthStack = DepthStackOptions{};
  EXPECT_THROW(exportKindOf(request), InputError);  // a depth stack goes into a folder
  request.out = "stack";
  EXPECT_EQ(exportKindOf(request), ExportKind::DepthStack);
}

TEST(ExportJob, CutOutsideTheBlockIsAnError) {
  ExportRequest request;
  request.out = artifact("outside.png");
  request.plane = CutPlane({0, 0, 90}, {0, 0, 1});
  EXPECT_THROW(runExport(demoModel(), request), InputError);
  EXPECT_FALSE(fs::exists(request.out));
}
