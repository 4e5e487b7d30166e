// Colour initialisation (fit/colour_fit.hpp, Mokume Sec. 5.3.1 / A.2.3): recover known colours of a
// synthetic block from its rendered faces, and improve the colour match on the real sample CN03.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>

#include "demo/demo_block.hpp"
#include "fit/colour_fit.hpp"
#include "fit/growth_field_fit.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {

double colourError(glm::vec3 a, glm::vec3 b) {
  return glm::length(a - b);
}

}  // namespace

TEST(ColourFit, RecoversTheColoursOfASyntheticBlock) {
  Project truth = demoProject(7);
  truth.params.faceTintB = {1.08f, 1.02f, 0.95f};  // one face lit differently
  truth.params.faceTintE = {0.93f, 0.95f, 1.0f};
  const GrowthRates rates = truth.effectiveRates();
  const WoodModel model(truth.block, truth.params, rates);
  std::array<Image, 6> photos;
  for (FaceId f : kAllFaces) photos[faceIndex(f)] = renderFace(model, f, {128, 128}, 2);

  WoodParameters start = truth.params;  // wrong colours and neutral tints
  start.earlywoodColor = {0.6f, 0.6f, 0.6f};
  start.latewoodColor = {0.3f, 0.3f, 0.3f};
  start.sapwoodEarlywoodColor = {0.7f, 0.7f, 0.7f};
  start.sapwoodLatewoodColor = {0.5f, 0.5f, 0.5f};
  start.faceTintB = start.faceTintE = glm::vec3(1.0f);
  const ColourFitResult fit = fitColours(truth.block, start, rates, photos);
  std::printf("[colour] %d samples, %d iterations, %.2f s; L1 per face before/after:", fit.samples,
              fit.iterations, fit.seconds);
  for (int f = 0; f < 6; ++f) std::printf(" %.3f/%.3f", fit.l1Before[f], fit.l1After[f]);
  const WoodParameters& p = fit.params;
  std::printf(
      "\n[colour] earlywood (%.3f %.3f %.3f) truth (%.3f %.3f %.3f); latewood (%.3f %.3f %.3f) truth "
      "(%.3f %.3f %.3f); tint B (%.3f %.3f %.3f)\n",
      p.earlywoodColor.x, p.earlywoodColor.y, p.earlywoodColor.z, truth.params.earlywoodColor.x,
      truth.params.earlywoodColor.y, truth.params.earlywoodColor.z, p.latewoodColor.x, p.latewoodColor.y,
      p.latewoodColor.z, truth.params.latewoodColor.x, truth.params.latewoodColor.y,
      truth.params.latewoodColor.z, p.faceTintB.x, p.faceTintB.y, p.faceTintB.z);
  for (int f = 0; f < 6; ++f) {
    EXPECT_LT(fit.l1After[f], 0.5 * fit.l1Before[f]) << f;
    EXPECT_LT(fit.l1After[f], 0.03) << f;
  }
  // Colour and tint trade off (the penalty keeps tints near 1), so compare what the faces show:
  // tinted heartwood colours of face B, and the untinted ones of face A.
  EXPECT_LT(colourError(p.earlywoodColor * p.faceTintA, truth.params.earlywoodColor * truth.params.faceTintA),
            0.05);
  EXPECT_LT(colourError(p.latewoodColor * p.faceTintA, truth.params.latewoodColor * truth.params.faceTintA),
            0.05);
  EXPECT_LT(colourError(p.earlywoodColor * p.faceTintB, truth.params.earlywoodColor * truth.params.faceTintB),
            0.05);
}

TEST(ColourFit, RefusesWithoutPhotos) {
  const Project demo = demoProject(7);
  EXPECT_THROW(fitColours(demo.block, demo.params, demo.effectiveRates(), {}), InputError);
}
