#include "texture/shading_layers.hpp"

#include <stdexcept>

#include "render/wood_model.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

enum Group { kRings, kLatewood, kPores, kRays, kFibres, kGroups };

// The parameters each group's layer reads (kernels/wood.glsl, WoodLayers); a group's layer is shared by
// candidates whose keys are equal. The seed drives every random feature.
std::vector<float> keyOf(const WoodParameters& p, int group) {
  switch (group) {
    case kRings:
      return {p.seed,
              p.ringOffset,
              p.ringProfile0,
              p.ringProfile1,
              p.ringProfile2,
              p.ringProfile3,
              p.ringProfile4,
              p.ringProfile5,
              p.ringProfile6,
              p.ringProfile7,
              p.mottleStrength > 0.0f ? 1.0f : 0.0f,
              p.mottleScale};
    case kLatewood:
      return {p.ringOffset, p.latewoodFraction, p.transition, p.boundarySoftness};
    case kPores:
      return {p.seed,           p.ringOffset,       p.latewoodFraction,
              p.transition,     p.boundarySoftness, p.poreRadiusEarly,
              p.poreRadiusLate, p.poreDensityEarly, p.poreDensityLate,
              p.poreCellSize,   p.poreLength,       p.poreEarlyTaper,
              p.poreZone,       p.poreEarlyThinning};
    case kRays:
      return {
          p.seed,    p.rayOpacity > 0.0f ? 1.0f : 0.0f, p.rayDensity, p.rayLength, p.raySpacing, p.rayHeight,
          p.rayWidth};
    default:
      return {p.seed, p.fiberStrength > 0.0f ? 1.0f : 0.0f, p.fiberWidth, p.fiberLength};
  }
}

constexpr int kFloatsPerPoint[kGroups] = {3, 1, 1, 1, 1};  // rings: profile, ring noise, mottle

}  // namespace

std::vector<Image> renderCandidateCrops(const std::vector<const WoodModel*>& models,
                                        const std::vector<FaceCrop>& crops,
                                        const std::vector<std::vector<WoodLocation>>& locations, int samples,
                                        ShadingCounts* counts, const Progress& progress) {
  const std::size_t n = models.size(), cropCount = crops.size();
  // Per group: the distinct keys (their first candidate computes the layer) and each candidate's key.
  std::array<std::vector<std::size_t>, kGroups> owners;  // candidate index of each distinct key
  std::array<std::vector<std::size_t>, kGroups> keyOfCandidate;
  for (int g = 0; g < kGroups; ++g) {
    std::vector<std::vector<float>> keys;
    for (std::size_t c = 0; c < n; ++c) {
      const std::vector<float> key = keyOf(models[c]->params(), g);
      std::size_t u = 0;
      while (u < keys.size() && keys[u] != key) ++u;
      if (u == keys.size()) keys.push_back(key), owners[g].push_back(c);
      keyOfCandidate[g].push_back(u);
    }
  }
  // layers[g][u * cropCount + k]: group g's floats for distinct key u on crop k.
  std::array<std::vector<std::vector<float>>, kGroups> layers;
  struct Item {
    int group;
    std::size_t key, crop;
  };
  std::vector<Item> items;
  for (int g = 0; g < kGroups; ++g) {
    layers[g].resize(owners[g].size() * cropCount);
    for (std::size_t u = 0; u < owners[g].size(); ++u)
      for (std::size_t k = 0; k < cropCount; ++k) items.push_back({g, u, k});
  }
  parallelRows(
      static_cast<int>(items.size()),
      [&](int i) {
        const Item& item = items[i];
        const WoodMaterial& material = models[owners[item.group][item.key]]->material();
        const std::vector<WoodLocation>& at = locations[item.crop];
        std::vector<float>& out = layers[item.group][item.key * cropCount + item.crop];
        out.resize(at.size() * kFloatsPerPoint[item.group]);
        WoodLayers l{};
        for (std::size_t p = 0; p < at.size(); ++p) switch (item.group) {
            case kRings:
              material.ringLayers(at[p], l);
              out[3 * p] = l.ringProfile, out[3 * p + 1] = l.ringNoise, out[3 * p + 2] = l.mottle;
              break;
            case kLatewood:
              out[p] = material.latewoodLayer(at[p]);
              break;
            case kPores:
              out[p] = material.poreLayer(at[p]);
              break;
            case kRays:
              out[p] = material.rayLayer(at[p]);
              break;
            default:
              out[p] = material.fiberLayer(at[p]);
          }
        if (counts) counts->layers[item.group] += at.size();
      },
      progress.part(0.0, 0.6));

  std::vector<Image> rendered(n * cropCount);
  parallelRows(
      static_cast<int>(rendered.size()),
      [&](int item) {
        const std::size_t c = item / cropCount, k = item % cropCount;
        const FaceCrop& crop = crops[k];
        const std::vector<WoodLocation>& at = locations[k];
        if (at.size() != static_cast<std::size_t>(crop.width) * crop.height * samples * samples)
          throw std::logic_error("renderCandidateCrops: the locations are not of this crop");
        const float* layer[kGroups];
        for (int g = 0; g < kGroups; ++g) layer[g] = layers[g][keyOfCandidate[g][c] * cropCount + k].data();
        const WoodMaterial& material = models[c]->material();
        const int face = faceIndex(crop.face);
        Image out(crop.width, crop.height, 3);
        const float weight = 1.0f / (samples * samples);
        std::size_t p = 0;
        for (int y = 0; y < crop.height; ++y)
          for (int x = 0; x < crop.width; ++x) {
            glm::vec3 sum(0.0f);
            for (int i = 0; i < samples * samples; ++i, ++p) {
              const WoodLayers l{layer[kLatewood][p],     layer[kPores][p],     layer[kRays][p],
                                 layer[kFibres][p],       layer[kRings][3 * p], layer[kRings][3 * p + 1],
                                 layer[kRings][3 * p + 2]};
              sum += material.compose(at[p], l, face).color;
            }
            float* q = out.pixel(x, y);
            q[0] = sum.x * weight, q[1] = sum.y * weight, q[2] = sum.z * weight;
          }
        rendered[item] = std::move(out);
        if (counts) counts->composed += at.size();
      },
      progress.part(0.6, 1.0));
  return rendered;
}

}  // namespace kerf
