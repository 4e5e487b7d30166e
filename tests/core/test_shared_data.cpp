// Real data from ../shared (a Mokume cube photographed by its authors). Skips where it is absent.
#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>

#include "io/image.hpp"
#include "io/project.hpp"

using namespace kerf;
namespace fs = std::filesystem;

TEST(SharedData, MokumeSampleCN03LoadsAsASampleFolder) {
  const fs::path folder = fs::path(KERF_SHARED_DIR) / "data" / "mokume" / "CN03";
  if (!fs::is_directory(folder))
    GTEST_SKIP() << "reference data not found at " << folder << " (../shared absent)";
  const Project project = loadDocument(folder);
  EXPECT_EQ(project.block.size(), glm::vec3(40.0f));
  for (FaceId face : kAllFaces) {
    const fs::path photo = project.facePhotos[faceIndex(face)];
    ASSERT_FALSE(photo.empty()) << faceLetter(face);
    const Image image = readImage(photo);
    EXPECT_EQ(image.width, 256);
    EXPECT_EQ(image.height, 256);
    // A wood photo: not black, not white.
    double mean = 0;
    for (float v : image.pixels) mean += v;
    mean /= image.pixels.size();
    EXPECT_GT(mean, 0.1) << faceLetter(face);
    EXPECT_LT(mean, 0.9) << faceLetter(face);
  }
}

TEST(SharedData, CorruptImageGivesAClearError) {
  const fs::path bad = fs::path(KERF_TEST_ARTIFACTS) / "corrupt.png";
  { std::ofstream(bad) << "this is not a png"; }
  try {
    readImage(bad);
    FAIL() << "corrupt image accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("corrupt.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readImage(fs::path(KERF_TEST_ARTIFACTS) / "missing.png"), std::exception);
}
