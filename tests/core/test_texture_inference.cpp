// Texture inference (texture/texture_inference.hpp, issue 7): a synthetic round trip - faces rendered from
// known detail parameters (with another random seed than the inference uses, so only the statistics can
// match), inference from perturbed parameters, recovery within the tolerances measured and stated in
// docs/texture.md - plus determinism, cancellation and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stop_token>

#include "demo/demo_block.hpp"

#include "noise_images.hpp"
#include "schema_checks.hpp"
#include "texture/detail_space.hpp"
#include "texture/texture_inference.hpp"
#include "texture_fixture.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {

const test::TextureSynthetic& synthetic() {
  return test::textureSynthetic();
}

WoodParameters perturbedStart(const WoodParameters& truth) {
  WoodParameters start = truth;
  start.seed = 3;
  start.poreRadiusEarly *= 1.7f;
  start.poreCellSize *= 0.6f;
  start.raySpacing *= 1.8f;
  start.fiberStrength += 0.3f;
  return start;
}

// Small and fast: the default crops (two of 96 px per face), four parameters, no colour refit.
TextureInferenceOptions fastOptions() {
  TextureInferenceOptions options;
  options.parameters = {"pores.radius_earlywood", "pores.cell_size", "rays.spacing", "fibers.strength"};
  options.refitColours = false;
  options.fullFaceReport = false;
  return options;
}

// Smaller still, for comparing runs with each other: one 64 px crop per face, one sweep, no coarse grid.
TextureInferenceOptions comparisonOptions() {
  TextureInferenceOptions options = fastOptions();
  options.coarseSearch = false;
  options.search.maxSweeps = 1;
  options.loss.cropsPerFace = 1;
  options.loss.cropSize = 64;
  return options;
}

double relativeError(float value, float truth) {
  return std::abs(value - truth) / truth;
}

// The round trip with the given search: the default (no coarse grid, 4 sweeps) or with the coarse grid.
void expectRecoversKnownDetail(const TextureInferenceOptions& search, bool poreSizesApart) {
  const test::TextureSynthetic& s = synthetic();
  const WoodParameters start = perturbedStart(s.truth.params);
  int previews = 0;
  TextureInferenceOptions options = fastOptions();
  options.search = search.search;
  options.coarseSearch = search.coarseSearch;
  options.preview = [&](const WoodParameters&) { ++previews; };
  const TextureInferenceResult r = inferTexture(s.truth.block, start, s.rates, s.photos, options);
  for (const std::string& line : formatTextureInferenceReport(r)) std::printf("%s\n", line.c_str());
  const WoodParameters& t = s.truth.params;
  std::printf(
      "pore radius %.4f (truth %.4f), pore spacing %.4f (%.4f), ray spacing %.4f (%.4f), fibre "
      "strength %.3f (%.3f)\n",
      r.params.poreRadiusEarly, t.poreRadiusEarly, r.params.poreCellSize, t.poreCellSize, r.params.raySpacing,
      t.raySpacing, r.params.fiberStrength, t.fiberStrength);
  EXPECT_LT(r.lossAfter, r.lossBefore);
  EXPECT_GT(previews, 0);
  // Pores placed without a lattice (issue 16) leave no period that gives their spacing away, and at
  // 12.8 px/mm a 0.12 mm pore is 1.5 px: the statistics see the pores' size relative to their spacing
  // (how much of the wood they cover, how clustered) better than both scales apart. Measured with this
  // seed (2026-12-07): the default search radius 0.099 mm, spacing 0.349 mm for a truth of 0.12 / 0.40
  // (both within 25 %, ratio 0.285 vs 0.30); with the coarse grid 0.071 / 0.231 (the ratio right, both
  // scales about halved by its "x0.5 pores").
  EXPECT_LT(
      relativeError(r.params.poreRadiusEarly / r.params.poreCellSize, t.poreRadiusEarly / t.poreCellSize),
      0.25);
  if (poreSizesApart) {
    EXPECT_LT(relativeError(r.params.poreRadiusEarly, t.poreRadiusEarly), 0.25);
    EXPECT_LT(relativeError(r.params.poreCellSize, t.poreCellSize), 0.25);
  }
  // No claim on the ray spacing here: among this chestnut's dense pores the loss does not see it. At the
  // true parameters (seed 3) it scored 0.60 / 0.75 / 0.90 / 1.10 / 1.30 / 1.62 / 2.00 mm as 0.295 / 0.241 /
  // 0.243 / 0.247 / 0.234 / 0.246 / 0.237 (2026-12-07): the 0.99 mm this search used to find was the
  // layouts' luck. RecoversTheRaySpacingOfAPoreFreeBlock below asks for it where the rays show.
  EXPECT_LT(std::abs(r.params.fiberStrength - t.fiberStrength), 0.15);
  for (FaceId face : kAllFaces) {
    const FaceTextureReport& f = r.faces[faceIndex(face)];
    EXPECT_TRUE(f.hasPhoto);
    EXPECT_LT(f.after.style, f.before.style) << faceLetter(face);
  }
  // The demo's pith runs along y: B and D are end grain, the others side grain.
  EXPECT_EQ(r.faces[faceIndex(FaceId::B)].orientation.grain, FaceGrain::EndGrain);
  EXPECT_EQ(r.faces[faceIndex(FaceId::D)].orientation.grain, FaceGrain::EndGrain);
  EXPECT_NE(r.faces[faceIndex(FaceId::A)].orientation.grain, FaceGrain::EndGrain);
}

}  // namespace

// The default search: no coarse grid, 4 sweeps, parameters the loss does not see settled at once (issue 16
// item 6).
TEST(TextureInference, RecoversKnownDetailOfASyntheticBlock) {
  const TextureInferenceOptions defaults;
  expectRecoversKnownDetail(defaults, true);
}

// `kerf-cli texture --coarse --sweeps 8` (the default before 2026-12-07): the same parameters but the pores'
// two scales, which the grid halves together.
TEST(TextureInference, RecoversKnownDetailOfASyntheticBlockWithTheCoarseGrid) {
  TextureInferenceOptions search;
  search.coarseSearch = true;
  search.search.maxSweeps = 8;
  expectRecoversKnownDetail(search, false);
}

// The rays' spacing, where the rays show: the same block without pores (as in a diffuse-porous wood whose
// vessels are under a pixel), searched from 1.8x the true spacing. Measured (2026-12-07): 0.78 mm for 0.9;
// at the true parameters the loss is lowest at 0.9 of 0.6 .. 2.0 mm.
TEST(TextureInference, RecoversTheRaySpacingOfAPoreFreeBlock) {
  const test::TextureSynthetic& s = synthetic();
  WoodParameters truth = s.truth.params;
  truth.poreDensityEarly = 0;
  truth.poreDensityLate = 0;
  const WoodModel model(s.truth.block, truth, s.rates);
  std::array<Image, 6> photos;
  for (FaceId face : kAllFaces) photos[faceIndex(face)] = renderFace(model, face, {512, 512}, 2);
  WoodParameters start = truth;
  start.seed = 3;
  start.raySpacing *= 1.8f;
  start.fiberStrength += 0.3f;
  TextureInferenceOptions options = fastOptions();
  options.parameters = {"rays.spacing", "fibers.strength"};
  const TextureInferenceResult r = inferTexture(s.truth.block, start, s.rates, photos, options);
  std::printf("ray spacing %.3f (truth %.3f), fibre strength %.3f (%.3f)\n", r.params.raySpacing,
              truth.raySpacing, r.params.fiberStrength, truth.fiberStrength);
  EXPECT_LT(relativeError(r.params.raySpacing, truth.raySpacing), 0.25);
  EXPECT_LT(std::abs(r.params.fiberStrength - truth.fiberStrength), 0.15);
}

TEST(TextureInference, IsDeterministic) {
  const test::TextureSynthetic& s = synthetic();
  TextureInferenceOptions options = comparisonOptions();
  const WoodParameters start = perturbedStart(s.truth.params);
  const TextureInferenceResult a = inferTexture(s.truth.block, start, s.rates, s.photos, options);
  const TextureInferenceResult b = inferTexture(s.truth.block, start, s.rates, s.photos, options);
  EXPECT_EQ(a.params, b.params);
  EXPECT_EQ(a.lossAfter, b.lossAfter);
}

// Leave-one-face-out (fit/held_out_faces.hpp): face C's photo replaced by noise and a tint learned from it
// change nothing when C is held out, and change the result when it is not.
TEST(TextureInference, UsesNothingOfAHeldOutPhoto) {
  const test::TextureSynthetic& s = synthetic();
  TextureInferenceOptions options = comparisonOptions();
  options.refitColours = true;  // the colour step reads the photos too
  options.heldOut.insert(FaceId::C);
  const int c = faceIndex(FaceId::C);
  std::array<Image, 6> garbage = s.photos;
  garbage[c] = kerf::testing::noisePhoto(s.photos[c].width, s.photos[c].height);
  const WoodParameters start = perturbedStart(s.truth.params);
  WoodParameters learnedTint = start;
  learnedTint.faceTintC = {1.3f, 0.8f, 0.9f};

  const TextureInferenceResult clean = inferTexture(s.truth.block, start, s.rates, s.photos, options);
  const TextureInferenceResult held = inferTexture(s.truth.block, learnedTint, s.rates, garbage, options);
  EXPECT_EQ(held.params, clean.params);
  EXPECT_EQ(held.lossBefore, clean.lossBefore);
  EXPECT_EQ(held.lossAfter, clean.lossAfter);
  EXPECT_FALSE(clean.faces[c].hasPhoto);
  EXPECT_EQ(clean.params.faceTintC, WoodParameters{}.faceTintC);
  EXPECT_EQ(formatTextureInferenceReport(held).front().rfind("held out (leave-one-face-out): face C;", 0),
            0u);

  options.heldOut = {};
  const TextureInferenceResult leaked = inferTexture(s.truth.block, learnedTint, s.rates, garbage, options);
  EXPECT_NE(leaked.lossBefore, clean.lossBefore);
  EXPECT_FALSE(leaked.params == clean.params);
}

TEST(TextureInference, StopsWhenCancelled) {
  const test::TextureSynthetic& s = synthetic();
  std::stop_source stop;
  stop.request_stop();
  EXPECT_THROW(inferTexture(s.truth.block, s.truth.params, s.rates, s.photos, fastOptions(),
                            Progress{nullptr, stop.get_token()}),
               Cancelled);
}

TEST(TextureInference, RefusesMissingAndMisshapenPhotosAndUnknownParameters) {
  const test::TextureSynthetic& s = synthetic();
  EXPECT_THROW(inferTexture(s.truth.block, s.truth.params, s.rates, {}, fastOptions()), InputError);
  std::array<Image, 6> wrong = s.photos;
  wrong[2] = Image(512, 256, 3);  // a cube's face is square
  EXPECT_THROW(inferTexture(s.truth.block, s.truth.params, s.rates, wrong, fastOptions()), InputError);
  TextureInferenceOptions options = fastOptions();
  options.parameters = {"growth.ring_width"};
  EXPECT_THROW(inferTexture(s.truth.block, s.truth.params, s.rates, s.photos, options), InputError);
}

TEST(DetailSpace, EncodingRoundTrips) {
  const WoodParameters params = demoProject(7).params;
  const std::vector<DetailCoordinate> coordinates = allDetailCoordinates();
  const WoodParameters back = decodeDetail(params, coordinates, encodeDetail(params, coordinates));
  for (const DetailCoordinate& c : coordinates)
    EXPECT_NEAR(detailValue(back, c), detailValue(params, c), 1e-3f * std::max(1.0f, detailValue(params, c)))
        << c.id;
}

// The search space comes from the schema's `search` column: each such parameter is a coordinate over its
// range, and moving the coordinates changes only parameters the schema marks as texture-fitted.
TEST(DetailSpace, ComesFromTheSchemaAndChangesOnlyTextureFittedParameters) {
  const std::vector<DetailCoordinate> coordinates = allDetailCoordinates();
  for (const ParamSpec& spec : parameterSchema()) {
    const auto it = std::find_if(coordinates.begin(), coordinates.end(),
                                 [&](const DetailCoordinate& c) { return c.id == spec.id; });
    ASSERT_EQ(it != coordinates.end(), spec.search.searched) << spec.id;
    if (it == coordinates.end()) continue;
    EXPECT_EQ(it->lo, spec.search.lo) << spec.id;
    EXPECT_EQ(it->hi, spec.search.hi) << spec.id;
    EXPECT_EQ(it->logScale, spec.search.scale == ParamScale::Log) << spec.id;
  }
  const WoodParameters params = demoProject(7).params;
  for (const double u : {0.0, 1.0}) {
    const WoodParameters moved =
        decodeDetail(params, coordinates, std::vector<double>(coordinates.size(), u));
    EXPECT_GT(test::expectOnlyFittedParametersChanged(params, moved, FitBy::Texture), 10) << "u = " << u;
  }
}

// The whole search (every detail parameter, coarse grid, colour refit) from a start far from the truth.
// About 2-4 minutes on 2 cores, hence disabled; run it with --gtest_also_run_disabled_tests. It reports
// how close each parameter comes (docs/texture.md lists a run) and asserts only the loss and the pores.
TEST(TextureInference, DISABLED_FullRoundTripAllParameters) {
  const test::TextureSynthetic& s = synthetic();
  WoodParameters start = perturbedStart(s.truth.params);
  start.rayHeight *= 2.0f;
  start.poreLength *= 0.5f;
  start.fiberWidth *= 2.0f;
  start.poreDarkness *= 0.6f;
  TextureInferenceOptions options;
  options.loss.cropsPerFace = 4;
  options.loss.cropSize = 128;
  const TextureInferenceResult r = inferTexture(s.truth.block, start, s.rates, s.photos, options);
  for (const std::string& line : formatTextureInferenceReport(r)) std::printf("%s\n", line.c_str());
  for (const DetailCoordinate& c : allDetailCoordinates()) {
    const float truth = detailValue(s.truth.params, c), from = detailValue(start, c),
                found = detailValue(r.params, c);
    std::printf("  %-26s truth %8.4f  start %8.4f  found %8.4f  (%+.0f %%)\n", c.id.c_str(), truth, from,
                found, 100.0 * (found - truth) / std::max(1e-6f, std::abs(truth)));
  }
  EXPECT_LT(r.lossAfter, r.lossBefore);
  EXPECT_LT(relativeError(r.params.poreRadiusEarly, s.truth.params.poreRadiusEarly), 0.25);
}
