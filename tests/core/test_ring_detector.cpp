// Ring localization measured (docs/rings.md): (a) on faces rendered by Kerf's own model for several
// wood types, against the true ring boundaries; (b) on the real Mokume sample CN03 against the
// authors' U-Net output (another method, not ground truth). The thresholds sit a margin below the
// measured values, so a regression fails them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "demo/demo_block.hpp"
#include "io/image.hpp"
#include "io/preset_files.hpp"
#include "io/project.hpp"
#include "params/presets.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "rings/contours.hpp"
#include "rings/ring_detector.hpp"
#include "rings/ring_metrics.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

constexpr int kFacePixels = 256;  // Mokume's 256 px per 40 mm face
constexpr float kPxPerMm = kFacePixels / 40.0f;

const fs::path& artifacts() {
  static const fs::path dir = [] {
    fs::path d = fs::path(KERF_TEST_ARTIFACTS) / "rings";
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

Image greyToRgb(const Image& grey) {
  Image out(grey.width, grey.height, 3);
  for (int y = 0; y < grey.height; ++y)
    for (int x = 0; x < grey.width; ++x)
      for (int c = 0; c < 3; ++c) out.pixel(x, y)[c] = grey.pixel(x, y)[0];
  return out;
}

struct Totals {
  long detected = 0, detectedNear = 0, reference = 0, referenceNear = 0;
  void add(const RingAgreement& a) {
    detected += a.detectedPixels;
    reference += a.referencePixels;
    detectedNear += std::lround(a.precision * a.detectedPixels);
    referenceNear += std::lround(a.recall * a.referencePixels);
  }
  double precision() const { return detected ? double(detectedNear) / detected : 0; }
  double recall() const { return reference ? double(referenceNear) / reference : 0; }
};

// All six faces of a 40 mm block of `presetId` (on the demo block's geometry), photo look applied.
Totals measureSynthetic(const std::string& presetId, std::uint32_t seed) {
  const auto presets = loadPresets(KERF_PRESETS_DIR);
  const Preset* preset = findPreset(presets, presetId);
  if (!preset) throw InputError("no preset " + presetId);
  Project project = demoProject(seed);
  project.params = preset->applyTo(project.params);
  const WoodModel model(project);
  const ClassicalRingDetector detector;
  Totals totals;
  for (FaceId face : kAllFaces) {
    const glm::ivec2 size(kFacePixels, kFacePixels);
    Image photo = renderFace(model, face, size, 2);
    applyPhotoLook(photo, face, seed);
    const ClassicalRingResult result = detector.detect(photo, kPxPerMm);
    const Image truth = trueRingPixels(model, face, size);
    const Image ridges = ringRidgePixels(result.arl);
    const RingAgreement a = compareRingPixels(ridges, truth, kPxPerMm);
    totals.add(a);
    std::printf(
        "  %-8s %c  precision %.3f  recall %.3f  (%ld / %ld px)  sharpness -:%.2f +:%.2f  width %.1f px\n",
        presetId.c_str(), faceLetter(face), a.precision, a.recall, a.detectedPixels, a.referencePixels,
        result.sharpness[0], result.sharpness[1], result.ringWidthPx);
    const std::string stem = presetId + "_" + faceLetter(face);
    writeImage(artifacts() / (stem + "_photo.png"), photo);
    writeImage(artifacts() / (stem + "_arl.png"), greyToRgb(result.arl));
    writeImage(artifacts() / (stem + "_truth.png"), greyToRgb(truth));
  }
  std::printf("%-8s all faces: precision %.3f recall %.3f\n", presetId.c_str(), totals.precision(),
              totals.recall());
  return totals;
}

}  // namespace

TEST(RingDetector, RejectsEmptyPhotos) {
  const ClassicalRingDetector detector;
  EXPECT_THROW(detector.localize(Image(), 6.4f), InputError);
  EXPECT_THROW(detector.localize(Image(16, 16, 3), 0.0f), InputError);
}

TEST(RingDetector, OutputHasThePhotoSizeAndRange) {
  Project project = demoProject(3);
  const WoodModel model(project);
  const Image photo = renderFace(model, FaceId::B, {96, 80}, 1);
  const Image arl = ClassicalRingDetector().localize(photo, 96 / 40.0f);
  ASSERT_EQ(arl.width, 96);
  ASSERT_EQ(arl.height, 80);
  ASSERT_EQ(arl.channels, 1);
  for (float v : arl.pixels) {
    ASSERT_GE(v, 0.0f);
    ASSERT_LE(v, 1.0f);
  }
}

TEST(RingDetector, PicksTheSharpEdgeOfASawtoothProfile) {
  // Rings 4 mm apart along x at 6.4 px/mm: the tone rises slowly through each ring (earlywood ->
  // latewood) and drops sharply at the boundary, in both orientations of the image. The detected
  // boundaries must sit on the drops, not on the slow side.
  const float pxPerMm = 6.4f, ringPx = 4.0f * pxPerMm;
  for (int flip = 0; flip < 2; ++flip) {
    Image photo(192, 160, 3);
    Image truth(192, 160, 1);
    for (int y = 0; y < photo.height; ++y)
      for (int x = 0; x < photo.width; ++x) {
        const float u = flip ? photo.width - (x + 0.5f) : x + 0.5f;
        const float f = u / ringPx - std::floor(u / ringPx);
        const float tone = 0.75f - 0.35f * f;  // light earlywood, darker towards the latewood
        for (int c = 0; c < 3; ++c) photo.pixel(x, y)[c] = tone;
        const float uNext = flip ? photo.width - (x + 1.5f) : x + 1.5f;
        if (x + 1 < photo.width && std::floor(u / ringPx) != std::floor(uNext / ringPx))
          truth.pixel(x, y)[0] = 1;
      }
    const ClassicalRingResult result = ClassicalRingDetector().detect(photo, pxPerMm);
    const RingAgreement a = compareRingPixels(ringRidgePixels(result.arl), truth, 0.25f * pxPerMm);
    EXPECT_GT(a.precision, 0.9) << "flip " << flip;
    EXPECT_GT(a.recall, 0.9) << "flip " << flip;
    EXPECT_NEAR(result.ringWidthPx, ringPx, 2.0f) << "flip " << flip;
  }
}

TEST(RingDetector, IsUsableThroughTheInterface) {
  const std::unique_ptr<RingDetector> detector = std::make_unique<ClassicalRingDetector>();
  EXPECT_EQ(detector->name(), "classical");
  const Image arl = detector->localize(Image(32, 32, 3), 6.4f);  // flat grey: no rings, no crash
  ASSERT_EQ(arl.width, 32);
  for (float v : arl.pixels) EXPECT_EQ(v, 0.0f);
}

struct WoodCase {
  const char* preset;
  double minPrecision, minRecall;
};

class RingDetectorSynthetic : public ::testing::TestWithParam<WoodCase> {};

TEST_P(RingDetectorSynthetic, FindsTheTrueRingBoundariesWithin1mm) {
  const WoodCase& c = GetParam();
  const Totals t = measureSynthetic(c.preset, 7);
  EXPECT_GE(t.precision(), c.minPrecision) << c.preset;
  EXPECT_GE(t.recall(), c.minRecall) << c.preset;
}

INSTANTIATE_TEST_SUITE_P(Woods, RingDetectorSynthetic,
                         // Measured (seed 7, docs/rings.md): sugi 0.984/0.997, kuri 0.942/0.985,
                         // nara 0.928/0.998, maple 0.993/0.999, red_oak 0.907/0.988. Since pores are
                         // holes with a shadow (issue 16): kuri 0.859/0.892 (its latewood now holds
                         // pores, as chestnut's does: CN03's photos), nara 0.898/0.992, red_oak
                         // 0.848/0.981; the others unchanged. Since fibre streaks are a shade on the
                         // colour (they used to vanish on woods of faint rings): kuri 0.837/0.893 (its
                         // preset's fibres were set stronger, as CN03 shows), nara 0.895/0.991, maple
                         // 0.938/0.996 (its flat-sawn faces A, F: precision 0.78, the streaks across the
                         // faint wide ring figure), red_oak 0.841/0.980; sugi unchanged.
                         ::testing::Values(WoodCase{"sugi", 0.93, 0.95}, WoodCase{"kuri", 0.81, 0.86},
                                           WoodCase{"nara", 0.87, 0.95}, WoodCase{"maple", 0.92, 0.95},
                                           WoodCase{"red_oak", 0.82, 0.93}),
                         [](const auto& info) { return std::string(info.param.preset); });

TEST(RingDetector, AgreesWithTheMokumeUNetOnCN03) {
  const fs::path folder = fs::path(KERF_SHARED_DIR) / "data" / "mokume" / "CN03";
  if (!fs::is_directory(folder))
    GTEST_SKIP() << "reference data not found at " << folder << " (../shared absent)";
  const ClassicalRingDetector detector;
  Totals totals;
  for (FaceId face : kAllFaces) {
    const std::string letter(1, faceLetter(face));
    const Image photo = readImage(folder / (letter + "_col.png"));
    const Image unet = readImage(folder / (letter + "_arl-unet.png"));
    const float pxPerMm = photo.width / 40.0f;
    const ClassicalRingResult result = detector.detect(photo, pxPerMm);
    const RingAgreement a = compareRingPixels(ringRidgePixels(result.arl), ringRidgePixels(unet), pxPerMm);
    totals.add(a);
    std::printf(
        "  CN03 %c  ours near U-Net %.3f  U-Net near ours %.3f  (%ld / %ld px)  contours %zu vs %zu  "
        "sharpness -:%.2f +:%.2f\n",
        faceLetter(face), a.precision, a.recall, a.detectedPixels, a.referencePixels,
        extractContours(result.arl, face).size(), extractContours(unet, face).size(), result.sharpness[0],
        result.sharpness[1]);
    writeImage(artifacts() / ("CN03_" + letter + "_arl.png"), greyToRgb(result.arl));
  }
  std::printf("CN03 all faces: ours within 1 mm of U-Net %.3f, U-Net within 1 mm of ours %.3f\n",
              totals.precision(), totals.recall());
  // Measured: 0.791 and 0.805 (docs/rings.md). The U-Net is another method, not the truth: these
  // guard against regressions, they do not claim accuracy.
  EXPECT_GE(totals.precision(), 0.70);
  EXPECT_GE(totals.recall(), 0.72);
}
