// Training data for Kerf's learned ring detector (issue 18 item 1; the learned-inference paper trains on
// procedural data): faces of random blocks rendered by Kerf's own model, each with the ring-localization
// image it should produce (Mokume Eq. 1 of the true year at every pixel centre). The photo look, white
// balance, exposure, blur, noise, JPEG, saw marks and scratches are randomised further while training
// (scripts/train_ring_detector.py), so one rendered face serves many training crops.
//
// Usage: kerf_ring_training_data OUT_DIR [blocks=200] [first_seed=1] [--anatomy]
// --anatomy also randomises pores, rays, fibres and colours far beyond the species presets.
// Writes OUT_DIR/NNNNN_F_photo.png (RGB) and OUT_DIR/NNNNN_F_arl.png (grey) for the six faces of each block,
// and OUT_DIR/index.txt, one line per face: stem, preset, px/mm, pith distance (mm), knot (0/1).
// Deterministic for (blocks, first_seed). Not a test; docs/rings.md "The learned detector".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <string>

#include "demo/demo_block.hpp"
#include "field/growth_rates.hpp"
#include "field/pith_axis.hpp"
#include "io/image.hpp"
#include "params/builtin_presets.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "util/parallel.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

constexpr float kNominalPxPerMm = 6.4f;  // Mokume's 256 px per 40 mm face; the detector resamples to it

struct RandomBlock {
  Block block;
  WoodParameters params;
  std::vector<BlockKnot> knots;
  std::string preset;
  float pithDistance = 0;
  float pxPerMm = kNominalPxPerMm;
};

float uniform(std::mt19937& random, float lo, float hi) {
  return std::uniform_real_distribution<float>(lo, hi)(random);
}

// A knot leaving the pith through a random point of the block, leaning up the stem as branches do.
BlockKnot randomKnot(const WoodParameters& p, const Block& block, std::mt19937& random) {
  const PithAxis pith = PithAxis::fromAngles(p.pithOrigin, p.pithTilt, p.pithAzimuth);
  const glm::vec3 half = 0.5f * block.size();
  const glm::vec3 target(uniform(random, -0.6f, 0.6f) * half.x, uniform(random, -0.6f, 0.6f) * half.y,
                         uniform(random, -0.6f, 0.6f) * half.z);
  const glm::vec3 onPith = pith.origin + glm::dot(target - pith.origin, pith.direction) * pith.direction;
  BlockKnot knot;
  knot.origin = onPith;
  knot.direction = glm::normalize(
      target - onPith + uniform(random, 0.0f, 0.4f) * glm::length(target - onPith) * pith.direction);
  knot.speed = uniform(random, 0.04f, 0.14f);
  return knot;
}

RandomBlock randomBlock(std::uint32_t seed, bool anatomy) {
  std::mt19937 random(seed * 7919u + 17u);
  const std::vector<Preset>& presets = builtInPresets();
  RandomBlock b;
  const Preset& preset = presets[random() % presets.size()];
  b.preset = preset.id;
  WoodParameters& p = b.params;
  p = preset.parametersOnDefaults();
  p.seed = static_cast<float>(seed);
  // The pith: mostly outside the block (cut blocks), 5 % through it; along the block's y axis within 20 deg.
  const float angle = uniform(random, 0.0f, 2.0f * std::numbers::pi_v<float>);
  b.pithDistance = random() % 20 == 0 ? uniform(random, 0.0f, 20.0f)
                                      : std::exp(uniform(random, std::log(25.0f), std::log(450.0f)));
  p.pithOrigin = glm::vec3(b.pithDistance * std::cos(angle), 0.0f, b.pithDistance * std::sin(angle));
  p.pithTilt = uniform(random, 0.0f, 20.0f);
  p.pithAzimuth = uniform(random, -180.0f, 180.0f);
  // Beyond the presets: ring width, eccentric and wavy rings, the ring's profile.
  p.ringWidth = std::clamp(p.ringWidth * std::exp(uniform(random, -0.7f, 0.7f)), 0.7f, 9.0f);
  p.eccentricity = uniform(random, 0.0f, 0.35f);
  p.irregularity = uniform(random, 0.0f, 0.6f);
  p.waviness = uniform(random, 0.0f, 0.3f);
  p.ringOffset = uniform(random, 0.0f, 1.0f);
  p.latewoodFraction = std::clamp(p.latewoodFraction + uniform(random, -0.15f, 0.15f), 0.05f, 0.8f);
  p.transition = std::clamp(p.transition + uniform(random, -0.2f, 0.2f), 0.0f, 1.0f);
  p.boundarySoftness = std::clamp(p.boundarySoftness * std::exp(uniform(random, -1.0f, 1.0f)), 0.005f, 0.2f);
  p.seasonShading = std::clamp(p.seasonShading * uniform(random, 0.4f, 1.3f), 0.1f, 1.5f);
  if (random() % 3 == 0) {
    // A fitted-looking ring profile (Mokume Sec. 5.3.2's base colour), e.g. the earlywood pore band of oak.
    float* profile[8] = {&p.ringProfile0, &p.ringProfile1, &p.ringProfile2, &p.ringProfile3,
                         &p.ringProfile4, &p.ringProfile5, &p.ringProfile6, &p.ringProfile7};
    for (float* v : profile) *v = uniform(random, -0.3f, 0.6f);
  }
  if (anatomy) {
    // The anatomy beyond the presets (real wood varies more than 17 presets): pores from none to large
    // dark bands of several rows, rays, fibre streaks, colours from pale to dark and reddish.
    p.poreCellSize = std::exp(uniform(random, std::log(0.15f), std::log(1.0f)));
    p.poreRadiusEarly = uniform(random, 0.0f, 0.45f) * p.poreCellSize;
    p.poreRadiusLate = uniform(random, 0.0f, 0.3f) * p.poreCellSize;
    p.poreDensityEarly = uniform(random, 0.0f, 1.0f);
    p.poreDensityLate = uniform(random, 0.0f, 0.6f);
    p.poreLength = std::exp(uniform(random, std::log(0.5f), std::log(10.0f)));
    p.poreDarkness = uniform(random, 0.3f, 3.0f);
    p.raySpacing = std::exp(uniform(random, std::log(0.3f), std::log(3.0f)));
    p.rayWidth = uniform(random, 0.02f, 0.3f);
    p.rayOpacity = uniform(random, 0.0f, 0.8f);
    p.fiberStrength = uniform(random, 0.0f, 0.5f);
    const float shade = uniform(random, 0.5f, 1.15f), red = uniform(random, 0.9f, 1.15f);
    const glm::vec3 tint(shade * red, shade, shade / red);
    p.earlywoodColor = glm::clamp(p.earlywoodColor * tint, 0.0f, 1.0f);
    p.latewoodColor = glm::clamp(p.latewoodColor * tint * uniform(random, 0.7f, 1.1f), 0.0f, 1.0f);
  }
  b.pxPerMm = kNominalPxPerMm * std::exp(uniform(random, std::log(0.8f), std::log(1.25f)));
  if (random() % 4 == 0) {
    p.knotSmoothStem = uniform(random, 1.5f, 4.0f);
    b.knots.push_back(randomKnot(p, b.block, random));
  }
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR [blocks=200] [first_seed=1] [--anatomy]\n", argv[0]);
    return 2;
  }
  const fs::path out = argv[1];
  const int blocks = argc > 2 ? std::atoi(argv[2]) : 200;
  const int firstSeed = argc > 3 ? std::atoi(argv[3]) : 1;
  const bool anatomy = argc > 4 && std::string(argv[4]) == "--anatomy";
  fs::create_directories(out);
  std::ofstream index(out / "index.txt");
  for (int i = 0; i < blocks; ++i) {
    const std::uint32_t seed = static_cast<std::uint32_t>(firstSeed + i);
    const RandomBlock b = randomBlock(seed, anatomy);
    const GrowthRates rates = synthesizeGrowthRates(b.params, b.block);
    const WoodModel model(b.block, b.params, rates, b.knots);
    for (FaceId face : kAllFaces) {
      const glm::ivec2 size = b.block.faceImageSize(face, b.pxPerMm);
      Image photo = renderFace(model, face, size, 2);
      applyPhotoLook(photo, face, seed);
      Image arl(size.x, size.y, 1);
      parallelRows(size.y, [&](int y) {
        for (int x = 0; x < size.x; ++x) {
          const float year =
              model.material().year(b.block.pixelCenter(face, x, y, size)) - b.params.ringOffset;
          arl.pixel(x, y)[0] =
              std::pow(0.5f * (std::cos(2.0f * std::numbers::pi_v<float> * year) + 1.0f), 10.0f);
        }
      });
      char stem[32];
      std::snprintf(stem, sizeof stem, "%05u_%c", seed, faceLetter(face));
      writeImage(out / (std::string(stem) + "_photo.png"), photo);
      writeImage(out / (std::string(stem) + "_arl.png"), arl);
      index << stem << ' ' << b.preset << ' ' << b.pxPerMm << ' ' << b.pithDistance << ' ' << b.knots.size()
            << '\n';
    }
    std::printf("block %d/%d (%s, pith %.0f mm, %zu knot)\n", i + 1, blocks, b.preset.c_str(), b.pithDistance,
                b.knots.size());
    std::fflush(stdout);
  }
  return 0;
}
