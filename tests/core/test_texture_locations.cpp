// The texture search locates each crop point in the tree once and shades it for every candidate
// (texture/face_crops.hpp, texture/texture_objective.hpp). That holds only because no searched texture
// parameter moves a point; these tests check it over the whole search space, that the located render is
// the plain render pixel for pixel, and that a candidate which does move the points is rendered afresh.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "demo/demo_block.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "texture/detail_space.hpp"
#include "texture/face_crops.hpp"
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
