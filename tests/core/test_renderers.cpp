// CPU renderers: faces agree with point evaluation, cuts are oriented like faces, cancel and progress work.
#include <gtest/gtest.h>

#include <cmath>

#include <atomic>

#include "demo/demo_block.hpp"
#include "render/batch_evaluator.hpp"
#include "render/renderers.hpp"
#include "render/unfolded_cross.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {
const Project& demo() {
  static const Project project = demoProject();
  return project;
}
}  // namespace

TEST(Renderers, FacePixelsAreTheModelAtPixelCentres) {
  const WoodModel model(demo());
  const glm::ivec2 size(40, 40);
  for (FaceId face : {FaceId::A, FaceId::D, FaceId::E}) {
    const Image image = renderFace(model, face, size);
    for (glm::ivec2 px : {glm::ivec2(0, 0), glm::ivec2(17, 31), glm::ivec2(39, 5)}) {
      const glm::vec3 expected =
          model.evaluate(model.block().pixelCenter(face, px.x, px.y, size), faceIndex(face)).color;
      const float* got = image.pixel(px.x, px.y);
      EXPECT_FLOAT_EQ(got[0], expected.x);
      EXPECT_FLOAT_EQ(got[2], expected.z);
    }
  }
}

TEST(Renderers, CutJustInsideAFaceLooksLikeThatFace) {
  const WoodModel model(demo());
  const float pxPerMm = 1.6f;  // 64 px over 40 mm
  for (FaceId face : kAllFaces) {
    const FaceFrame f = model.block().face(face);
    const CutPlane plane(f.center - 1e-3f * f.normal, f.normal);
    const Image cut = renderCut(model, plane, pxPerMm);
    const Image faceImage = renderFace(model, face, model.block().faceImageSize(face, pxPerMm));
    ASSERT_EQ(cut.width, faceImage.width) << faceLetter(face);
    ASSERT_EQ(cut.height, faceImage.height) << faceLetter(face);
    double difference = 0;
    for (int y = 0; y < cut.height; ++y)
      for (int x = 0; x < cut.width; ++x) {
        EXPECT_EQ(cut.pixel(x, y)[3], 1.0f);
        for (int c = 0; c < 3; ++c) difference += std::abs(cut.pixel(x, y)[c] - faceImage.pixel(x, y)[c]);
      }
    EXPECT_LT(difference / (cut.width * cut.height * 3), 0.01)
        << "cut and face " << faceLetter(face) << " disagree";
  }
}

TEST(Renderers, SlantedCutIsTransparentOutsideTheBlock) {
  const WoodModel model(demo());
  const Image cut = renderCut(model, CutPlane({0, 0, 0}, {1, 1, 1}), 2.0f);
  int transparent = 0, opaque = 0;
  for (int y = 0; y < cut.height; ++y)
    for (int x = 0; x < cut.width; ++x) (cut.pixel(x, y)[3] == 0.0f ? transparent : opaque)++;
  EXPECT_GT(transparent, cut.width * cut.height / 8);  // a hexagon inside its bounding rectangle
  EXPECT_GT(opaque, cut.width * cut.height / 2);
  EXPECT_THROW(renderCut(model, CutPlane({0, 0, 100}, {0, 0, 1}), 2.0f), InputError);
  EXPECT_THROW(renderCut(model, CutPlane({0, 0, 0}, {0, 0, 1}), 1000.0f), InputError);  // 40000 px
}

TEST(Renderers, ReportProgressAndCancel) {
  const WoodModel model(demo());
  std::atomic<double> last{0};
  Progress progress{[&](double f) { last = std::max(last.load(), f); }, {}};
  renderFaces(model, 0.5f, 1, progress);
  EXPECT_DOUBLE_EQ(last.load(), 1.0);

  std::stop_source stop;
  stop.request_stop();
  EXPECT_THROW(renderFace(model, FaceId::A, {64, 64}, 1, {nullptr, stop.get_token()}), Cancelled);
}

TEST(Renderers, UnfoldedCrossPlacesFacesInTheirSlots) {
  const WoodModel model(demo());
  const auto faces = renderFaces(model, 0.4f);  // 16 px faces
  const Image cross = unfoldedCross(faces, model.block(), 0.0f);
  EXPECT_EQ(cross.width, 4 * 16);
  EXPECT_EQ(cross.height, 3 * 16);
  EXPECT_EQ(cross.pixel(16 + 3, 4)[1], faces[faceIndex(FaceId::B)].pixel(3, 4)[1]);
  EXPECT_EQ(cross.pixel(48 + 2, 16 + 9)[0], faces[faceIndex(FaceId::F)].pixel(2, 9)[0]);
  EXPECT_EQ(cross.pixel(0, 0)[0], 0.0f);  // empty corner
}

TEST(Renderers, BatchEvaluationEqualsPointEvaluation) {
  const WoodModel model(demo());
  std::vector<glm::vec3> points;
  for (int i = 0; i < 10000; ++i)
    points.emplace_back(-19.0f + (i % 97) * 0.4f, -19.0f + (i % 89) * 0.43f, -19.0f + (i % 83) * 0.45f);
  std::vector<float> years(points.size());
  std::vector<glm::vec3> colors(points.size());
  evaluateYears(model, points, years);
  evaluateColors(model, points, colors);
  for (std::size_t i = 0; i < points.size(); i += 37) {
    EXPECT_EQ(years[i], model.material().year(points[i]));
    EXPECT_EQ(colors[i], model.evaluate(points[i]).color);
  }
  EXPECT_THROW(evaluateYears(model, points, std::span<float>(years).first(3)), std::invalid_argument);
}
