#pragma once
// Files the core tests write: a fresh scratch folder per case, and golden-image checks. Both live under
// KERF_TEST_ARTIFACTS (the build tree), goldens in KERF_GOLDEN_DIR (tests/golden).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "image/image_difference.hpp"
#include "io/image.hpp"

namespace kerf::testing {

// KERF_TEST_ARTIFACTS/group/name, emptied.
inline std::filesystem::path scratchFolder(const std::string& group, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(KERF_TEST_ARTIFACTS) / group / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// KERF_TEST_ARTIFACTS/group/name, its folder created (the file itself is left as it is).
inline std::filesystem::path artifactFile(const std::string& group, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(KERF_TEST_ARTIFACTS) / group;
  std::filesystem::create_directories(dir);
  return dir / name;
}

// Images are stored as 8-bit PNG, so 1/255 of rounding is expected; pores and ring edges may move by a
// pixel between compilers, which the share tolerance absorbs.
struct GoldenTolerance {
  float pixel = 0.08f;
  double maxShareOver = 0.005;
  double maxMeanAbs = 0.004;
};

// Compares `rendered` with tests/golden/<name>.png (8-bit to 8-bit); the rendering is kept as
// golden-actual-<name>.png. KERF_UPDATE_GOLDEN=1 accepts it as the new golden.
inline void checkGolden(const Image& rendered, const std::string& name,
                        const GoldenTolerance& tolerance = {}) {
  namespace fs = std::filesystem;
  const fs::path golden = fs::path(KERF_GOLDEN_DIR) / (name + ".png");
  const fs::path actual = fs::path(KERF_TEST_ARTIFACTS) / ("golden-actual-" + name + ".png");
  writeImage(actual, rendered);
  if (std::getenv("KERF_UPDATE_GOLDEN")) {
    writeImage(golden, rendered);
    return;
  }
  ASSERT_TRUE(fs::exists(golden)) << "missing golden " << golden << "; the rendering is in " << actual
                                  << " (set KERF_UPDATE_GOLDEN=1 to accept it)";
  const Image reference = readImage(golden, true);
  const Image roundTripped = readImage(actual, true);
  const ImageDifference d = compareImages(roundTripped, reference, tolerance.pixel);
  EXPECT_LT(d.meanAbs, tolerance.maxMeanAbs) << name << ": see " << actual;
  EXPECT_LT(d.shareOverTolerance, tolerance.maxShareOver) << name << ": see " << actual;
}

}  // namespace kerf::testing
