// The texture search locates each crop point in the tree once and shades it for every candidate
// (texture/face_crops.hpp, texture/texture_objective.hpp). That holds only because no searched texture
// parameter moves a point; these tests check it over the whole search space, that the located render is
// the plain render pixel for pixel, and that a candidate which does move the points is rendered afresh.
// And that candidates rendered together, sharing the layers they agree on (texture/shading_layers.hpp),
// get the pixels of the plain render, whatever parameter they change.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "demo/demo_block.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "texture/detail_space.hpp"
#include "texture/face_crops.hpp"
#include "texture/shading_layers.hpp"
#include "texture/texture_objective.hpp"

using namespace kerf;

namespace {

bool sameLocation(const WoodLocation& a, const WoodLocation& b) {
  return a.year == b.year && a.knotDarkness == b.knotDarkness && a.knotShade == b.knotShade &&
         a.c.height == b.c.height && a.c.radius == b.c.radius && a.c.azimuth == b.c.azimuth &&
         a.c.x == b.c.x && a.c.y == b.c.y;
}

// Points through the whole block (centred on the origin), on a 7 x 7 x 7 grid.
std::vector<glm::vec3> pointsIn(const Block& block) {
  std::vector<glm::vec3> out;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      for (int k = 0; k < 7; ++k)
        out.push_back((glm::vec3(i + 0.5f, j + 0.5f, k + 0.5f) / 7.0f - 0.5f) * block.size());
  return out;
}

}  // namespace

TEST(TextureLocations, NoSearchedParameterMovesAPoint) {
  const Project project = demoProject(7);
  ASSERT_GT(project.params.distortionAmplitude, 0.0f) << "the grain's wobble must be on to be tested";
  const GrowthRates rates = project.effectiveRates();
  const WoodModel base(project.block, project.params, rates);
  const std::vector<glm::vec3> points = pointsIn(project.block);
  const std::vector<DetailCoordinate> coordinates = allDetailCoordinates();
  ASSERT_GT(coordinates.size(), 10u);
  for (std::size_t i = 0; i < coordinates.size(); ++i)
    for (double end : {0.0, 1.0}) {
      std::vector<double> u = encodeDetail(project.params, coordinates);
      u[i] = end;
      const WoodParameters changed = decodeDetail(project.params, coordinates, u);
      const WoodModel model(project.block, changed, rates);
      int moved = 0;
      for (const glm::vec3& p : points)
        moved += sameLocation(model.material().locate(p), base.material().locate(p)) ? 0 : 1;
      EXPECT_EQ(moved, 0) << coordinates[i].id << " at " << end << " moves points of the wood";
    }
}

TEST(TextureLocations, ALocatedCropIsThePlainRenderPixelForPixel) {
  const Project project = demoProject(7);
  const GrowthRates rates = project.effectiveRates();
  const WoodModel base(project.block, project.params, rates);
  WoodParameters other = project.params;  // other pores, rays and fibres: the same places
  other.poreCellSize *= 1.5f, other.raySpacing *= 0.7f, other.fiberStrength = 0.8f;
  const WoodModel model(project.block, other, rates);
  const FaceCrop crop{FaceId::C, 30, 40, 24, 20};
  for (int samples : {1, 2}) {
    const std::vector<WoodLocation> located = locateFaceCrop(base, crop, {256, 256}, samples);
    const Image a = renderFaceCrop(model, crop, located, samples);
    const Image b = renderFaceCrop(model, crop, {256, 256}, samples);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_TRUE(a.pixels == b.pixels) << samples << " samples: the located render differs";
  }
  EXPECT_THROW(renderFaceCrop(model, crop, locateFaceCrop(base, crop, {256, 256}, 1), 2), std::logic_error);
}

TEST(TextureLocations, ACandidateThatMovesThePointsIsRenderedAfresh) {
  const Project project = demoProject(7);
  const GrowthRates rates = project.effectiveRates();
  const WoodModel truth(project.block, project.params, rates);
  std::array<Image, 6> photos;
  for (FaceId face : kAllFaces) photos[faceIndex(face)] = renderFace(truth, face, {128, 128}, 1);
  TextureLossOptions options;
  options.cropsPerFace = 1;
  options.cropSize = 48;
  WoodParameters wobblier = project.params;  // not a texture parameter: it moves every point
  wobblier.distortionAmplitude *= 3.0f;
  const TextureObjective fromTruth(project.block, rates, project.params, photos, options);
  const TextureObjective fromWobblier(project.block, rates, wobblier, photos, options);
  const double reused = fromTruth.evaluate({wobblier})[0].loss;
  EXPECT_EQ(reused, fromWobblier.evaluate({wobblier})[0].loss);
  EXPECT_NE(reused, fromTruth.evaluate({project.params})[0].loss);
}

// Every parameter of the schema that leaves the points where they are, changed one at a time (each
// component, twice), the candidates rendered together: every crop is the plain render, bit for bit. A
// parameter missing from a layer's key would give a candidate another's layer and fail here.
TEST(ShadingLayers, CandidatesRenderedTogetherAreThePlainRenderBitForBit) {
  Project project = demoProject(7);
  project.params.mottleStrength = 0.3f;  // every layer on
  project.params.ringColorVariation = 0.2f;
  const GrowthRates rates = project.effectiveRates();
  const WoodModel base(project.block, project.params, rates);
  const std::vector<FaceCrop> crops{{FaceId::B, 30, 40, 20, 16}, {FaceId::C, 100, 60, 16, 20}};
  const int samples = 2;
  std::vector<std::vector<WoodLocation>> located;
  for (const FaceCrop& crop : crops) located.push_back(locateFaceCrop(base, crop, {256, 256}, samples));
  const std::vector<glm::vec3> points = pointsIn(project.block);
  std::vector<WoodParameters> candidates{project.params};
  for (std::size_t i = 0; i < parameterSchema().size(); ++i)
    for (std::size_t component = 0; component < project.params.components(i).size(); ++component)
      for (const float factor : {0.8f, 1.3f}) {
        WoodParameters changed = project.params;
        float& value = changed.components(i)[component];
        const ParamSpec& spec = parameterSchema()[i];
        value = std::clamp(value * factor + (factor - 1.0f) * 0.1f, spec.hardMin, spec.hardMax);
        if (spec.kind == ParamKind::Integer) value = std::round(value + (factor > 1.0f ? 1.0f : -1.0f));
        if (changed == project.params) continue;
        const WoodModel model(project.block, changed, rates);
        bool moves = false;
        for (const glm::vec3& p : points)
          moves = moves || !sameLocation(model.material().locate(p), base.material().locate(p));
        if (!moves) candidates.push_back(changed);
      }
  ASSERT_GT(candidates.size(), 60u);
  std::vector<std::unique_ptr<WoodModel>> models;
  std::vector<const WoodModel*> pointers;
  for (const WoodParameters& params : candidates) {
    models.push_back(std::make_unique<WoodModel>(project.block, params, rates));
    pointers.push_back(models.back().get());
  }
  ShadingCounts counts;
  const std::vector<Image> together = renderCandidateCrops(pointers, crops, located, samples, &counts);
  ASSERT_EQ(together.size(), candidates.size() * crops.size());
  for (std::size_t c = 0; c < candidates.size(); ++c)
    for (std::size_t k = 0; k < crops.size(); ++k) {
      const Image alone = renderFaceCrop(*models[c], crops[k], {256, 256}, samples);
      EXPECT_TRUE(together[c * crops.size() + k].pixels == alone.pixels)
          << "candidate " << c << ", crop " << k;
    }
  // Shared: fewer layer points than candidates x points (most candidates agree on most layers).
  std::uint64_t total = 0;
  for (const auto& l : located) total += l.size();
  EXPECT_EQ(counts.composed, candidates.size() * total);
  for (const auto& layer : counts.layers) EXPECT_LT(layer.load(), candidates.size() * total / 2);
}
