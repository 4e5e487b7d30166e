// Unusual inputs that are not errors (catalogue in docs/reliability.md): what Kerf makes of them is exact.
// 16-bit, grey, alpha and CMYK photos become the same RGB 0..1 values; a log without knots is a stem; a
// sample folder with missing faces opens with those faces empty.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include "bad_input_files.hpp"
#include "io/image.hpp"
#include "io/log_data_import.hpp"
#include "io/project.hpp"

using namespace kerf;
using namespace kerf::bad;

namespace {

fs::path folder(const std::string& name) {
  const fs::path dir = fs::path(KERF_TEST_ARTIFACTS) / "accepted_inputs" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Image constant(int channels, std::initializer_list<float> values) {
  Image image(4, 3, channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = *(values.begin() + i % channels);
  return image;
}

void expectRgb(const Image& image, glm::vec3 rgb, float tolerance) {
  ASSERT_EQ(image.channels, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.pixel(x, y)[c], rgb[c], tolerance) << x << "," << y;
}

}  // namespace

TEST(AcceptedInputs, SixteenBitPhotoKeepsItsPrecision) {
  const fs::path file = folder("16bit") / "A_col.png";
  writeImage(file, constant(3, {0.1f, 0.5f, 0.9f}), 16);
  expectRgb(readImage(file), {0.1f, 0.5f, 0.9f}, 1.0f / 65535);
}

TEST(AcceptedInputs, GreyPhotoIsReplicatedToRgb) {
  const fs::path file = folder("grey") / "A_col.png";
  writeImage(file, constant(1, {0.4f}));
  expectRgb(readImage(file), glm::vec3(std::round(0.4f * 255) / 255), 1e-6f);
}

TEST(AcceptedInputs, AlphaIsDropped) {
  const fs::path file = folder("alpha") / "A_col.png";
  writeImage(file, constant(4, {0.2f, 0.6f, 1.0f, 0.0f}));  // fully transparent: the colour still counts
  expectRgb(readImage(file), {std::round(0.2f * 255) / 255, std::round(0.6f * 255) / 255, 1.0f}, 1e-6f);
}

TEST(AcceptedInputs, CmykPhotoIsConvertedToRgb) {
  const fs::path file = folder("cmyk") / "A_col.tif";
  OIIO::ImageSpec spec(4, 3, 4, OIIO::TypeDesc::UINT8);
  spec.channelnames = {"C", "M", "Y", "K"};
  spec.attribute("tiff:ColorSpace", "CMYK");
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out && out->open(file.string(), spec));
  const Image cmyk = constant(4, {0.0f, 0.5f, 1.0f, 0.0f});
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, cmyk.pixels.data()) && out->close());
  // C, M, Y, K = 0, 0.5, 1, 0 is R, G, B = 1, 0.5, 0 (8-bit rounding of 0.5 twice).
  expectRgb(readImage(file), {1.0f, 0.5f, 0.0f}, 2.5f / 255);
}

TEST(AcceptedInputs, SampleFolderWithMissingFacesOpensWithThoseFacesEmpty) {
  const fs::path dir = folder("missing_faces");
  writePhoto(dir / "A_col.png", 16, 16);
  writePhoto(dir / "E_col.png", 16, 16);
  const Project project = loadDocument(dir);
  for (FaceId face : kAllFaces)
    EXPECT_EQ(project.facePhotos[faceIndex(face)].empty(), face != FaceId::A && face != FaceId::E);
}

TEST(AcceptedInputs, LogWithoutKnotsIsAStem) {
  const fs::path file = folder("log_without_knots") / "stem.kerflog";
  writeText(file, R"({"format": "kerf-log", "version": 1, "stem": {"height_step_mm": 100, "azimuths": 3,
                      "pith_mm": [[0, 0], [0, 0]], "radii_mm": [50, 50, 50, 60, 60, 60]}})");
  const LogModel log = loadLog(file);
  EXPECT_TRUE(log.knots.empty());
  EXPECT_FLOAT_EQ(log.stem.height(), 100.0f);
  EXPECT_NEAR(log.stem.radiusAt(50.0f, 1.0f), 55.0f, 1e-3f);
}
