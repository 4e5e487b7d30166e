#include "appearance/exemplar_pyramids.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace kerf {
namespace {

constexpr int kColour = 3;
// The fixed point's step: 1/4096 of a weighted feature (the weights make 1 a large difference), unless a
// feature is too large for 16 bits at that step.
constexpr float kFinestStep = 4096.0f;
constexpr float kLargest = 32000.0f;

std::vector<std::uint8_t> angleBins(const std::vector<float>& radians) {
  std::vector<std::uint8_t> out(radians.size());
  std::transform(radians.begin(), radians.end(), out.begin(), angleBin);
  return out;
}

// The guidance channels that some photo has (not zero everywhere): a channel that is zero in every
// exemplar adds the same to every candidate's distance, so it cannot change which one is nearest.
std::vector<int> keptChannels(const std::vector<Exemplar>& exemplars) {
  std::vector<int> kept;
  for (int c = 0; c < kGuidanceChannels; ++c) {
    bool used = false;
    for (const Exemplar& e : exemplars)
      for (std::size_t i = c; i < e.guidance.features.size() && !used; i += kGuidanceChannels)
        used = e.guidance.features[i] != 0.0f;
    if (used) kept.push_back(c);
  }
  return kept;
}

// The colour weight, or 1 without one: the colours stay packed then too (the vote reads them there).
float colourFactor(float colourWeight) {
  return colourWeight > 0.0f ? colourWeight : 1.0f;
}

float fixedPointScale(const std::vector<Exemplar>& exemplars, const std::vector<int>& kept,
                      float colourWeight) {
  float largest = colourFactor(colourWeight);  // colours are about [0, 1]
  for (const Exemplar& e : exemplars) {
    for (std::size_t i = 0; i < e.guidance.features.size(); i += kGuidanceChannels)
      for (int c : kept) largest = std::max(largest, std::abs(e.guidance.features[i + c]));
    for (float v : e.colour.pixels) largest = std::max(largest, colourFactor(colourWeight) * std::abs(v));
  }
  return largest * kFinestStep > kLargest ? kLargest / largest : kFinestStep;
}

Image halveImage(const Image& image) {
  Image out(std::max(1, image.width / 2), std::max(1, image.height / 2), image.channels);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < image.channels; ++c) {
        float sum = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx)
            sum +=
                image.pixel(std::min(2 * x + dx, image.width - 1), std::min(2 * y + dy, image.height - 1))[c];
        out.pixel(x, y)[c] = 0.25f * sum;
      }
  return out;
}

ExemplarLevel exemplarLevel(const PreparedExemplars& p, const Image& colour, const SurfaceGuidance& g) {
  ExemplarLevel e;
  e.w = g.width;
  e.h = g.height;
  e.packed = PackedImage<Short4>(g.width, g.height, 0, p.chunks);
  e.packed.setColours(colour.pixels.data(), p.colourScale, 1.0f);
  e.packed.setFeatures(g.features.data(), kGuidanceChannels, p.kept, p.scale);
  e.angle = angleBins(g.grainAngle);
  return e;
}

TargetLevel emptyTarget(int w, int h, int chunks, int radius) {
  TargetLevel t;
  t.w = w;
  t.h = h;
  t.packed = PackedImage<Float4>(w, h, radius, chunks);
  t.colour.assign(static_cast<std::size_t>(w) * h * kColour, 0.0f);
  return t;
}

}  // namespace

namespace {

// Exemplar by exemplar, all its levels (the finest reads it as it is, coarser ones halve it); with
// `release`, each exemplar's guidance and colour are freed once packed (the peak memory of a project with
// large photos).
std::shared_ptr<const PreparedExemplars> prepare(std::vector<Exemplar>& exemplars,
                                                 const GuidedSynthesisOptions& options, bool release) {
  if (exemplars.empty()) throw InputError("photo-true appearance: no photo to take the texture from");
  if (options.patchRadius < 1 || options.levels < 1 || options.passes < 1)
    throw InputError("photo-true appearance: patch radius, levels and passes must be at least 1");
  for (const Exemplar& e : exemplars)
    if (e.colour.width != e.guidance.width || e.colour.height != e.guidance.height)
      throw InputError("photo-true appearance: a photo and its guidance differ in size");
  auto p = std::make_shared<PreparedExemplars>();
  const int r = options.patchRadius;
  p->patchRadius = r;
  p->colourWeight = options.colourWeight;
  p->kept = keptChannels(exemplars);
  p->chunks = packedChunks(static_cast<int>(p->kept.size()));
  p->scale = fixedPointScale(exemplars, p->kept, options.colourWeight);
  p->colourScale = colourFactor(options.colourWeight) * p->scale;
  // Beyond the farthest a turned sample reaches from the patch centre: no sample needs clamping.
  const float reach = std::ceil(r * std::sqrt(2.0f)) + 1.0f;
  std::vector<std::vector<ExemplarLevel>> byExemplar(exemplars.size());
  for (std::size_t i = 0; i < exemplars.size(); ++i) {
    SurfaceGuidance guidance;
    Image colour;
    for (int level = 0; level < options.levels; ++level) {
      if (level > 0) {
        guidance = halveGuidance(level == 1 ? exemplars[i].guidance : guidance);
        colour = halveImage(level == 1 ? exemplars[i].colour : colour);
      }
      ExemplarLevel e = level == 0 ? exemplarLevel(*p, exemplars[i].colour, exemplars[i].guidance)
                                   : exemplarLevel(*p, colour, guidance);
      const float margin = std::ceil(float(exemplars[i].marginPx) / float(1 << level)) + reach;
      e.minX = margin, e.minY = margin, e.maxX = e.w - 1 - margin, e.maxY = e.h - 1 - margin;
      byExemplar[i].push_back(std::move(e));
    }
    if (release) exemplars[i] = Exemplar{};
  }
  // A level is used only while every exemplar still has room for turned patches.
  for (int level = 0; level < options.levels; ++level) {
    bool usable = true;
    for (const auto& levels : byExemplar) usable = usable && levels[level].usable();
    if (!usable) {
      if (level == 0) throw InputError("photo-true appearance: a photo is too small for the patches");
      break;
    }
    p->levels.emplace_back();
    for (auto& levels : byExemplar) p->levels.back().push_back(std::move(levels[level]));
  }
  return p;
}

}  // namespace

std::shared_ptr<const PreparedExemplars> prepareExemplars(const std::vector<Exemplar>& exemplars,
                                                          const GuidedSynthesisOptions& options) {
  std::vector<Exemplar> copy = exemplars;
  return prepare(copy, options, false);
}

std::shared_ptr<const PreparedExemplars> prepareExemplars(std::vector<Exemplar>&& exemplars,
                                                          const GuidedSynthesisOptions& options) {
  return prepare(exemplars, options, true);
}

TargetLevel targetLevel(const PreparedExemplars& p, const SurfaceGuidance& g) {
  TargetLevel t = emptyTarget(g.width, g.height, p.chunks, p.patchRadius);
  t.packed.setFeatures(g.features.data(), kGuidanceChannels, p.kept, p.scale);
  t.packed.fillPad();
  t.angle = angleBins(g.grainAngle);
  return t;
}

std::vector<TargetLevel> targetLevels(const PreparedExemplars& p, const SurfaceGuidance& target) {
  std::vector<TargetLevel> out;
  SurfaceGuidance halved;
  for (std::size_t level = 0; level < p.levels.size(); ++level) {
    if (level > 0) halved = halveGuidance(level == 1 ? target : halved);
    out.push_back(targetLevel(p, level == 0 ? target : halved));
  }
  return out;
}

std::vector<TargetLevel> targetLevels(const PreparedExemplars& p, int index) {
  if (index < 0 || index >= static_cast<int>(p.levels.front().size()))
    throw InputError("photo-true appearance: no such exemplar");
  std::vector<TargetLevel> out;
  for (const std::vector<ExemplarLevel>& level : p.levels) {
    const ExemplarLevel& e = level[index];
    TargetLevel t = emptyTarget(e.w, e.h, p.chunks, p.patchRadius);
    for (int y = 0; y < e.h; ++y)
      for (int x = 0; x < e.w; ++x)
        for (int c = 1; c < p.chunks; ++c) t.packed.at(x, y)[c] = toFloat4(e.packed.at(x, y)[c]);
    t.packed.fillPad();
    t.angle = e.angle;
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace kerf
