// Ring localization measured (docs/rings.md): (a) on faces rendered by Kerf's own model for several
// wood types, against the true ring boundaries; (b) on the real Mokume sample CN03 against the
// authors' U-Net output (another method, not ground truth). The thresholds sit a margin below the
// measured values, so a regression fails them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <stop_token>
#include <string>

#include "demo/demo_block.hpp"
#include "io/image.hpp"
#include "io/preset_files.hpp"
#include "io/project.hpp"
#include "params/presets.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "rings/contours.hpp"
#include "rings/learned_ring_detector.hpp"
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

// All six faces of a 40 mm block of `presetId` (on the demo block's geometry), photo look applied, seen by
// `detector`. The demo block's wood and seeds are not among the learned detector's training blocks
// (bench/ring_training_data.cpp draws its own).
Totals measureSynthetic(const RingDetector& detector, const std::string& presetId, std::uint32_t seed) {
  const auto presets = loadPresets(KERF_PRESETS_DIR);
  const Preset* preset = findPreset(presets, presetId);
  if (!preset) throw InputError("no preset " + presetId);
  Project project = demoProject(seed);
  project.params = preset->applyTo(project.params);
  const WoodModel model(project);
  Totals totals;
  for (FaceId face : kAllFaces) {
    const glm::ivec2 size(kFacePixels, kFacePixels);
    Image photo = renderFace(model, face, size, 2);
    applyPhotoLook(photo, face, seed);
    const Image arl = detector.localize(photo, kPxPerMm);
    const Image truth = trueRingPixels(model, face, size);
    const Image ridges = ringRidgePixels(arl);
    const RingAgreement a = compareRingPixels(ridges, truth, kPxPerMm);
    totals.add(a);
    std::printf("  %-9s %-8s %c  precision %.3f  recall %.3f  (%ld / %ld px)\n", detector.name().c_str(),
                presetId.c_str(), faceLetter(face), a.precision, a.recall, a.detectedPixels,
                a.referencePixels);
    const std::string stem = detector.name() + "_" + presetId + "_" + faceLetter(face);
    writeImage(artifacts() / (presetId + "_" + faceLetter(face) + "_photo.png"), photo);
    writeImage(artifacts() / (stem + "_arl.png"), greyToRgb(arl));
    writeImage(artifacts() / (presetId + "_" + faceLetter(face) + "_truth.png"), greyToRgb(truth));
  }
  std::printf("%-9s %-8s all faces: precision %.3f recall %.3f\n", detector.name().c_str(), presetId.c_str(),
              totals.precision(), totals.recall());
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

// One wood seen by one detector (ringDetectorNamed): the suites below differ only in the detector.
template <const char* kDetector>
class SyntheticWood : public ::testing::TestWithParam<WoodCase> {
 protected:
  void check() const {
    const WoodCase& c = GetParam();
    const Totals t = measureSynthetic(ringDetectorNamed(kDetector), c.preset, 7);
    EXPECT_GE(t.precision(), c.minPrecision) << kDetector << " " << c.preset;
    EXPECT_GE(t.recall(), c.minRecall) << kDetector << " " << c.preset;
  }
};
constexpr char kClassical[] = "classical";
constexpr char kLearned[] = "learned";

class RingDetectorSynthetic : public SyntheticWood<kClassical> {};

TEST_P(RingDetectorSynthetic, FindsTheTrueRingBoundariesWithin1mm) {
  check();
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
                         // faint wide ring figure), red_oak 0.841/0.980; sugi unchanged. Since vessels,
                         // rays and fibres lie in the growth layers (kernels/wood.glsl inGrowthLayers):
                         // kuri 0.831/0.905, nara 0.900/0.993, maple 0.920/0.997 (face F 0.61: between
                         // its rings the fibre streaks now run along the ring figure and read as ring
                         // lines), red_oak 0.864/0.980; sugi 0.985/0.997.
                         ::testing::Values(WoodCase{"sugi", 0.93, 0.95}, WoodCase{"kuri", 0.81, 0.86},
                                           WoodCase{"nara", 0.87, 0.95}, WoodCase{"maple", 0.90, 0.95},
                                           WoodCase{"red_oak", 0.82, 0.93}),
                         [](const auto& info) { return std::string(info.param.preset); });

namespace {

// `detector` on CN03's six photos against the authors' U-Net maps; nullopt where ../shared is absent.
std::optional<Totals> measureCN03(const RingDetector& detector) {
  const fs::path folder = fs::path(KERF_SHARED_DIR) / "data" / "mokume" / "CN03";
  if (!fs::is_directory(folder)) return std::nullopt;
  Totals totals;
  for (FaceId face : kAllFaces) {
    const std::string letter(1, faceLetter(face));
    const Image photo = readImage(folder / (letter + "_col.png"));
    const Image unet = readImage(folder / (letter + "_arl-unet.png"));
    const float pxPerMm = photo.width / 40.0f;
    const Image arl = detector.localize(photo, pxPerMm);
    const RingAgreement a = compareRingPixels(ringRidgePixels(arl), ringRidgePixels(unet), pxPerMm);
    totals.add(a);
    std::printf("  CN03 %c %-9s near U-Net %.3f  U-Net near it %.3f  (%ld / %ld px)  contours %zu vs %zu\n",
                faceLetter(face), detector.name().c_str(), a.precision, a.recall, a.detectedPixels,
                a.referencePixels, extractContours(arl, face).size(), extractContours(unet, face).size());
    writeImage(artifacts() / ("CN03_" + letter + "_" + detector.name() + "_arl.png"), greyToRgb(arl));
  }
  std::printf("CN03 all faces, %s: within 1 mm of U-Net %.3f, U-Net within 1 mm of it %.3f\n",
              detector.name().c_str(), totals.precision(), totals.recall());
  return totals;
}

}  // namespace

TEST(RingDetector, AgreesWithTheMokumeUNetOnCN03) {
  const std::optional<Totals> totals = measureCN03(ClassicalRingDetector());
  if (!totals) GTEST_SKIP() << "reference data not found at " << KERF_SHARED_DIR << " (../shared absent)";
  // Measured: 0.791 and 0.805 (docs/rings.md). The U-Net is another method, not the truth: these
  // guard against regressions, they do not claim accuracy.
  EXPECT_GE(totals->precision(), 0.70);
  EXPECT_GE(totals->recall(), 0.72);
}

// --- The learned detector (issue 18 item 1; rings/learned_ring_detector.hpp) ---------------------------

TEST(LearnedRingDetector, OutputHasThePhotoSizeAndRangeAtAnyResolution) {
  const LearnedRingDetector detector;
  EXPECT_EQ(detector.name(), "learned");
  Project project = demoProject(3);
  const WoodModel model(project);
  // 40 mm at 2.4 px/mm and at 12 px/mm (the network runs at 6.4 px/mm), odd sizes on purpose.
  for (const glm::ivec2 size : {glm::ivec2(97, 81), glm::ivec2(481, 479)}) {
    const Image photo = renderFace(model, FaceId::B, size, 1);
    const Image arl = detector.localize(photo, size.x / 40.0f);
    ASSERT_EQ(arl.width, size.x);
    ASSERT_EQ(arl.height, size.y);
    ASSERT_EQ(arl.channels, 1);
    float top = 0;
    for (float v : arl.pixels) {
      ASSERT_GE(v, 0.0f);
      ASSERT_LE(v, 1.0f);
      top = std::max(top, v);
    }
    EXPECT_GT(top, 0.8f) << "no ring found on the demo's end grain at " << size.x << " px";
  }
  const Image grey = detector.localize(renderFace(model, FaceId::A, {64, 64}, 1), 1.6f);
  EXPECT_EQ(grey.width, 64);  // 1.6 px/mm, resampled 4x up for the network: still the photo's size out
  // The smallest face detection takes (kMinRingDetectionSide): padding must not fail.
  EXPECT_EQ(detector.localize(Image(4, 4, 3), 6.4f).width, 4);
  // The network's own probability (crisp = false): soft values, not the 0/1-profile of the crisp image.
  LearnedRingParams soft;
  soft.crisp = false;
  const Image probability =
      LearnedRingDetector(soft).localize(renderFace(model, FaceId::B, {128, 128}, 1), 3.2f);
  int between = 0;
  for (float v : probability.pixels) between += v > 0.1f && v < 0.9f;
  EXPECT_GT(between, 100) << "the probability should be soft at the band edges";
}

TEST(LearnedRingDetector, RejectsBadInputAndBadNetworksByName) {
  const LearnedRingDetector detector;
  EXPECT_THROW(detector.localize(Image(), 6.4f), InputError);
  EXPECT_THROW(detector.localize(Image(16, 16, 3), 0.0f), InputError);
  const std::string junk = "not an onnx network";
  try {
    LearnedRingDetector bad(std::as_bytes(std::span(junk)), "junk.onnx");
    FAIL() << "a broken network loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("junk.onnx"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ringDetectorNamed("learned").name(), "learned");
  EXPECT_EQ(ringDetectorNamed("classical").name(), "classical");
  EXPECT_THROW(ringDetectorNamed("unet"), InputError);
}

TEST(LearnedRingDetector, IsCancelled) {
  std::stop_source stop;
  stop.request_stop();
  EXPECT_THROW(LearnedRingDetector().localize(Image(64, 64, 3), 1.6f, Progress{nullptr, stop.get_token()}),
               Cancelled);
}

class LearnedRingDetectorSynthetic : public SyntheticWood<kLearned> {};

TEST_P(LearnedRingDetectorSynthetic, FindsTheTrueRingBoundariesWithin1mm) {
  check();
}

INSTANTIATE_TEST_SUITE_P(Woods, LearnedRingDetectorSynthetic,
                         // Measured (seed 7; the demo block's wood, none of the training blocks;
                         // docs/rings.md "The learned detector"): sugi 1.000/0.992, kuri 0.873/0.951,
                         // nara 0.745/0.480 (its 2 mm rings: half the boundaries missed), maple
                         // 1.000/0.992, red_oak 0.611/0.982 (ray fleck read as rings).
                         ::testing::Values(WoodCase{"sugi", 0.95, 0.95}, WoodCase{"kuri", 0.83, 0.90},
                                           WoodCase{"nara", 0.70, 0.43}, WoodCase{"maple", 0.95, 0.95},
                                           WoodCase{"red_oak", 0.56, 0.93}),
                         [](const auto& info) { return std::string(info.param.preset); });

TEST(LearnedRingDetector, AgreesWithTheMokumeUNetOnCN03) {
  const std::optional<Totals> totals = measureCN03(LearnedRingDetector());
  if (!totals) GTEST_SKIP() << "reference data not found at " << KERF_SHARED_DIR << " (../shared absent)";
  // CN03 was never seen in training (validation only). Measured 0.860 / 0.897 (the classical detector:
  // 0.791 / 0.805; docs/rings.md).
  EXPECT_GE(totals->precision(), 0.81);
  EXPECT_GE(totals->recall(), 0.85);
}
