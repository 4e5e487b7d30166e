#pragma once
// What the guided synthesis (appearance/guided_synthesis.hpp) reads, made once: the exemplars' pyramids
// packed for the patch distance (appearance/packed_patches.hpp: 16-bit fixed point, only the guidance
// channels some photo has), their colours and grain angle bins; and a target's levels, packed the same
// way (as floats, padded). PhotoTrueAppearance prepares its photos once and synthesises every surface
// from them, and a photographed face's own levels are its target (the same guidance on the same grid).
#include <cstdint>
#include <vector>

#include "appearance/guidance_features.hpp"
#include "appearance/guided_synthesis.hpp"
#include "appearance/packed_patches.hpp"

namespace kerf {

// An exemplar at one pyramid level: packed colour and features (the colours the vote copies too), its
// grain angle bins, and where patch centres may lie in it (so that a patch turned any way stays inside
// the photo and away from its damaged border).
struct ExemplarLevel {
  int w = 0, h = 0;
  PackedImage<Short4> packed;
  std::vector<std::uint8_t> angle;
  float minX = 0, maxX = 0, minY = 0, maxY = 0;
  bool usable() const { return maxX > minX && maxY > minY; }
};

struct PreparedExemplars {
  int patchRadius = 0;
  float colourWeight = 0;
  float scale = 1;        // the fixed point's: packed features are the features times it
  float colourScale = 1;  // packed colours are the colours times it (the colour weight, or 1, times scale)
  std::vector<int> kept;  // the guidance channels packed
  int chunks = 0;
  std::vector<std::vector<ExemplarLevel>> levels;  // [level][exemplar], finest first, all usable
};

// The target at one level: packed features (floats, padded by a patch radius: no sample is clamped) and
// colour estimate, the colour estimate as it is (RGB), the grain angle bins.
struct TargetLevel {
  int w = 0, h = 0;
  PackedImage<Float4> packed;
  std::vector<float> colour;
  std::vector<std::uint8_t> angle;
};

// The target's levels, finest first: from its guidance, or those of exemplar `index` itself.
std::vector<TargetLevel> targetLevels(const PreparedExemplars& prepared, const SurfaceGuidance& target);
std::vector<TargetLevel> targetLevels(const PreparedExemplars& prepared, int index);
// One level, from this guidance (a volume's later slices are refined at the finest level only).
TargetLevel targetLevel(const PreparedExemplars& prepared, const SurfaceGuidance& target);

}  // namespace kerf
