// Leave-one-face-out (issue 16 item 4, fit/held_out_faces.hpp): face sets as letters, and the proof that
// the growth-field fit uses nothing of a held-out face - its photo, ring image, traces, knot marks or an
// earlier tint replaced by garbage leave the fitted field and colours bit for bit the same.
#include <gtest/gtest.h>

#include "noise_images.hpp"
#include "ring_image_fixture.hpp"

#include <string>

#include "demo/demo_block.hpp"
#include "fit/growth_field_fit.hpp"
#include "io/project.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"

using namespace kerf;
using kerf::testing::noisePhoto;
using kerf::testing::noiseRingImage;

namespace {

std::string parseError(const std::string& text) {
  try {
    parseFaceSet(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The demo block's ring images (as a perfect detector would give them) and rendered photos.
struct Sample {
  Project truth = demoProject(7);
  GrowthFieldFitInput input;
  Sample() {
    const WoodModel model(truth.block, truth.params, truth.effectiveRates());
    const auto growth = [&](glm::vec3 p) { return static_cast<double>(model.evaluate(p).year); };
    for (FaceId face : kAllFaces) {
      input.rings[faceIndex(face)] = kerf::testing::renderRingImageOf(growth, truth.block, face, 96, 0.3f);
      input.photos[faceIndex(face)] = renderFace(model, face, {64, 64}, 1);
    }
  }
};

// Face C's inputs replaced by garbage: noise for its photo and ring image, a stray trace and a knot mark
// drawn on it.
GrowthFieldFitInput withGarbageOnC(GrowthFieldFitInput input) {
  const int c = faceIndex(FaceId::C);
  input.photos[c] = noisePhoto(input.photos[c].width, input.photos[c].height);
  input.rings[c] = noiseRingImage(input.rings[c].width, input.rings[c].height);
  input.traces.push_back(
      RingTrace{FaceId::C, {{4.0f, 6.0f}, {20.0f, 30.0f}, {36.0f, 33.0f}}, std::nullopt, TraceOrigin::Drawn});
  input.knotMarks.push_back(KnotMark{0, FaceId::C, {20.0f, 20.0f}});
  return input;
}

GrowthFieldFitOptions quickOptions() {
  GrowthFieldFitOptions options;
  options.fitAlternative = false;  // one field is enough to compare
  return options;
}

}  // namespace

TEST(FaceSet, ParsesLettersInAnyCase) {
  EXPECT_EQ(parseFaceSet("C").letters(), "C");
  EXPECT_EQ(parseFaceSet("ca").letters(), "AC");
  EXPECT_EQ(parseFaceSet("A, c").letters(), "AC");
  EXPECT_TRUE(parseFaceSet("").empty());
  EXPECT_TRUE(parseFaceSet("abcdef").all());
  EXPECT_EQ(parseFaceSet("AA").size(), 1);
}

TEST(FaceSet, RefusesOtherLettersNamingThem) {
  EXPECT_NE(parseError("G").find("'G'"), std::string::npos) << parseError("G");
  EXPECT_NE(parseError("AX").find("'X' in \"AX\" is not a face letter (faces are A..F)"), std::string::npos);
  EXPECT_NE(parseError("1").find("'1'"), std::string::npos);
}

TEST(HeldOutFaces, TheFitUsesNothingOfAHeldOutFace) {
  const Sample s;
  GrowthFieldFitInput held = s.input;
  held.heldOut.insert(FaceId::C);
  GrowthFieldFitInput heldGarbage = withGarbageOnC(held);
  WoodParameters learnedTint = s.truth.params;  // a tint an earlier fit may have learned from C's photo
  learnedTint.faceTintC = {1.3f, 0.8f, 0.9f};

  const GrowthFieldFitResult clean =
      fitGrowthFieldToSample(held, s.truth.block, s.truth.params, quickOptions());
  const GrowthFieldFitResult garbage =
      fitGrowthFieldToSample(heldGarbage, s.truth.block, learnedTint, quickOptions());
  ASSERT_TRUE(clean.rates && garbage.rates);
  EXPECT_TRUE(clean.report.coloursFitted);
  EXPECT_TRUE(garbage.params == clean.params) << "the fitted parameters differ";
  EXPECT_TRUE(garbage.rates->rates == clean.rates->rates) << "the fitted growth rates differ";
  EXPECT_EQ(garbage.knots.size(), clean.knots.size());
  EXPECT_EQ(clean.report.contoursPerFace[faceIndex(FaceId::C)], -1);  // no ring image read for C
  EXPECT_EQ(clean.params.faceTintC, WoodParameters{}.faceTintC);      // neutral: a prediction
  const std::vector<ReportLine> lines = formatGrowthFieldFitReport(garbage.report);
  EXPECT_EQ(lines.front().text.rfind("held out (leave-one-face-out): face C;", 0), 0u) << lines.front().text;

  // The same garbage not held out changes the fit: the comparison above would catch a leak.
  GrowthFieldFitInput used = heldGarbage;
  used.heldOut = {};
  const GrowthFieldFitResult leaked =
      fitGrowthFieldToSample(used, s.truth.block, learnedTint, quickOptions());
  EXPECT_FALSE(leaked.params == clean.params);
}

TEST(HeldOutFaces, AllSixFacesCannotBeHeldOut) {
  Sample s;
  s.input.heldOut = parseFaceSet("ABCDEF");
  try {
    fitGrowthFieldToSample(s.input, s.truth.block, s.truth.params);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("all six faces are held out"), std::string::npos) << e.what();
  }
}
