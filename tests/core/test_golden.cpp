// Golden images of the demo block's faces and of a slanted cut, compared with a tolerance.
// Regenerate after an intended change of the model with KERF_UPDATE_GOLDEN=1 and review the PNGs.
#include <gtest/gtest.h>

#include "test_files.hpp"

#include <cmath>

#include <cstdlib>
#include <filesystem>

#include "demo/demo_block.hpp"
#include "render/renderers.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

using kerf::testing::checkGolden;

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
