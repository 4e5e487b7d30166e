// Golden images of the demo block's faces and of a slanted cut, compared with a tolerance.
// Regenerate after an intended change of the model with KERF_UPDATE_GOLDEN=1 and review the PNGs.
#include <gtest/gtest.h>

#include <cmath>

#include <cstdlib>
#include <filesystem>

#include "demo/demo_block.hpp"
#include "render/renderers.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

// Images are stored as 8-bit PNG, so 1/255 of rounding is expected; pores and ring edges may move
// by a pixel between compilers, which the share tolerance absorbs.
constexpr float kPixelTolerance = 0.08f;
constexpr double kMaxShareOver = 0.005;
constexpr double kMaxMeanAbs = 0.004;

void checkGolden(const Image& rendered, const std::string& name) {
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
  const Image roundTripped = readImage(actual, true);  // compare 8-bit to 8-bit
  const ImageDifference d = compareImages(roundTripped, reference, kPixelTolerance);
  EXPECT_LT(d.meanAbs, kMaxMeanAbs) << name << ": see " << actual;
  EXPECT_LT(d.shareOverTolerance, kMaxShareOver) << name << ": see " << actual;
}

}  // namespace

TEST(Golden, DemoFaces) {
  const WoodModel model(demoProject());
  const auto faces = renderFaces(model, 2.0f, 2);  // 80 x 80 px
  for (FaceId face : kAllFaces)
    checkGolden(faces[faceIndex(face)], std::string("demo_face_") + faceLetter(face));
}

TEST(Golden, DemoSlantedCut) {
  const WoodModel model(demoProject());
  checkGolden(renderCut(model, CutPlane({2, -3, 1}, {0.3f, 1.0f, 0.6f}), 2.5f, 2), "demo_cut_slanted");
}
