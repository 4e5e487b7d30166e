// The bundled demo: a valid Mokume-style sample with its true parameters and a project.
#include <gtest/gtest.h>

#include <cmath>

#include <fstream>
#include <nlohmann/json.hpp>

#include "demo/demo_block.hpp"
#include "image/image_difference.hpp"
#include "render/renderers.hpp"

using namespace kerf;
namespace fs = std::filesystem;

TEST(Demo, WritesASampleFolderTheTruthAndAProject) {
  const fs::path dir = fs::path(KERF_TEST_ARTIFACTS) / "demo32";
  fs::remove_all(dir);
  DemoOptions options;
  options.facePixels = 32;
  options.samples = 1;
  const DemoFiles files = writeDemo(dir, options);

  const Project sample = loadDocument(dir);  // the folder alone is a Mokume-style sample
  for (FaceId face : kAllFaces) {
    ASSERT_FALSE(sample.facePhotos[faceIndex(face)].empty()) << faceLetter(face);
    EXPECT_EQ(readImageSize(sample.facePhotos[faceIndex(face)]), glm::ivec2(32, 32));
  }
  const Project project = loadProject(files.project);
  EXPECT_EQ(project.params, demoProject().params);
  EXPECT_FALSE(project.rates);  // synthesised from the parameters
  EXPECT_EQ(project.facePhotos[2], fs::absolute(files.photos[2]));

  std::ifstream in(files.truth);
  const nlohmann::json truth = nlohmann::json::parse(in);
  EXPECT_EQ(parametersFromJson(truth["parameters"]), project.params);
  EXPECT_EQ(growthRatesFromJson(truth["growth_rates"]).rates, project.effectiveRates().rates);
}

TEST(Demo, PhotoLookChangesThePictureButKeepsTheWood) {
  const WoodModel model(demoProject());
  const Image plain = renderFace(model, FaceId::A, {64, 64});
  Image photo = plain;
  applyPhotoLook(photo, FaceId::A, 7);
  const ImageDifference d = compareImages(photo, plain, 0.1f);
  EXPECT_GT(d.meanAbs, 0.005);  // lighting, white balance and noise are there
  EXPECT_LT(d.meanAbs, 0.08);   // but the rings are still the rings
  Image again = plain;
  applyPhotoLook(again, FaceId::A, 7);
  EXPECT_EQ(again.pixels, photo.pixels);
}
