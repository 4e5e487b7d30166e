#include "appearance/guided_synthesis.hpp"
#include "util/split_mix.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

constexpr int kColour = 3;
constexpr int kStride = kColour + kGuidanceChannels;

// One image of one pyramid level: colour and weighted features interleaved, and the grain angle.
struct Level {
  int w = 0, h = 0;
  std::vector<float> data;  // kStride floats per pixel
  std::vector<float> angle;
  float* at(int x, int y) { return &data[(static_cast<std::size_t>(y) * w + x) * kStride]; }
  const float* at(int x, int y) const { return &data[(static_cast<std::size_t>(y) * w + x) * kStride]; }
};

// An exemplar level and where patch centres may lie in it (so that a patch turned any way stays inside
// the photo and away from its damaged border).
struct ExemplarLevel : Level {
  float minX = 0, maxX = 0, minY = 0, maxY = 0;
  bool usable() const { return maxX > minX && maxY > minY; }
};

// The nearest-neighbour field's entry: exemplar, position, rotation (cos, sin of the angle that turns the
// exemplar's grain onto the target's) and the patch distance.
struct Match {
  int e = 0;
  float x = 0, y = 0;
  float c = 1, s = 0;
  float cost = std::numeric_limits<float>::max();
};

using Random = SplitMix;

Random lineRandom(std::uint32_t seed, int level, int pass, int sweep, int line) {
  std::uint64_t s = seed;
  s = s * 0x100000001B3ULL + static_cast<std::uint64_t>(level);
  s = s * 0x100000001B3ULL + static_cast<std::uint64_t>(pass);
  s = s * 0x100000001B3ULL + static_cast<std::uint64_t>(sweep);
  s = s * 0x100000001B3ULL + static_cast<std::uint64_t>(line);
  Random r{s};
  r.next();
  return r;
}

Level levelFrom(const Image* colour, const SurfaceGuidance& g) {
  Level level;
  level.w = g.width;
  level.h = g.height;
  level.data.assign(static_cast<std::size_t>(g.width) * g.height * kStride, 0.0f);
  level.angle = g.grainAngle;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      float* d = level.at(x, y);
      if (colour) std::copy_n(colour->pixel(x, y), kColour, d);
      std::copy_n(g.at(x, y), kGuidanceChannels, d + kColour);
    }
  return level;
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

class Synthesis {
 public:
  Synthesis(const std::vector<ExemplarLevel>& exemplars, Level& target, const GuidedSynthesisOptions& options,
            int level, bool coarsest)
      : ex_(exemplars), t_(target), o_(options), level_(level), r_(options.patchRadius), coarsest_(coarsest) {
    const float sigma = 0.5f * r_ + 0.5f;
    for (int dy = -r_; dy <= r_; ++dy)
      for (int dx = -r_; dx <= r_; ++dx)
        voteWeight_.push_back(std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma)));
  }

  std::vector<Match>& field() { return nnf_; }

  // Random candidates for every pixel (the coarsest level's start).
  void initialiseRandom() {
    nnf_.assign(static_cast<std::size_t>(t_.w) * t_.h, Match{});
    parallelRows(t_.h, [&](int y) {
      Random random = lineRandom(o_.seed, level_, -1, 0, y);
      for (int x = 0; x < t_.w; ++x) {
        Match& m = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        for (int k = 0; k < 6; ++k) tryGlobal(x, y, m, random, 0.0f);
      }
    });
  }

  // The field of the coarser level, carried to this one.
  void initialiseFrom(const std::vector<Match>& coarse, int coarseW, int coarseH) {
    nnf_.assign(static_cast<std::size_t>(t_.w) * t_.h, Match{});
    parallelRows(t_.h, [&](int y) {
      for (int x = 0; x < t_.w; ++x) {
        const int cx = std::min(x / 2, coarseW - 1), cy = std::min(y / 2, coarseH - 1);
        const Match& m = coarse[static_cast<std::size_t>(cy) * coarseW + cx];
        const float dx = x - (2 * cx + 0.5f), dy = y - (2 * cy + 0.5f);
        const ExemplarLevel& e = ex_[m.e];
        Match& out = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        out.e = m.e;
        out.x = std::clamp(2 * m.x + 0.5f + m.c * dx + m.s * dy, e.minX, e.maxX);
        out.y = std::clamp(2 * m.y + 0.5f - m.s * dx + m.c * dy, e.minY, e.maxY);
      }
    });
  }

  // One PatchMatch pass (a horizontal sweep with propagation and random search, then a vertical sweep with
  // propagation), then the vote. colourWeight 0: guidance only.
  void pass(int passIndex, float colourWeight) {
    const int dir = passIndex % 2 == 0 ? 1 : -1;
    parallelRows(t_.h, [&](int y) {
      Random random = lineRandom(o_.seed, level_, passIndex, 0, y);
      for (int i = 0; i < t_.w; ++i) {
        const int x = dir > 0 ? i : t_.w - 1 - i;
        Match& m = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        rescore(x, y, m, colourWeight);
        if (x - dir >= 0 && x - dir < t_.w)
          propagate(x, y, nnf_[static_cast<std::size_t>(y) * t_.w + x - dir], dir, 0, m, colourWeight);
        randomSearch(x, y, m, random, colourWeight);
      }
    });
    parallelRows(t_.w, [&](int x) {
      Random random = lineRandom(o_.seed, level_, passIndex, 1, x);
      for (int i = 0; i < t_.h; ++i) {
        const int y = dir > 0 ? i : t_.h - 1 - i;
        Match& m = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        if (y - dir >= 0 && y - dir < t_.h)
          propagate(x, y, nnf_[static_cast<std::size_t>(y - dir) * t_.w + x], 0, dir, m, colourWeight);
        tryGlobal(x, y, m, random, colourWeight);
      }
    });
    vote();
  }

  // Kwatra et al. 2005 Sec. 3 (M step): every pixel's colour is the weighted mean of what the patches
  // covering it say.
  void vote(bool centreOnly = false) {
    std::vector<float> colour(static_cast<std::size_t>(t_.w) * t_.h * kColour);
    parallelRows(t_.h, [&](int y) {
      for (int x = 0; x < t_.w; ++x) {
        float acc[kColour] = {0, 0, 0};
        float weightSum = 0;
        int k = 0;
        for (int dy = -r_; dy <= r_; ++dy)
          for (int dx = -r_; dx <= r_; ++dx, ++k) {
            if (centreOnly && (dx != 0 || dy != 0)) continue;
            const int nx = x - dx, ny = y - dy;
            if (nx < 0 || ny < 0 || nx >= t_.w || ny >= t_.h) continue;
            const Match& m = nnf_[static_cast<std::size_t>(ny) * t_.w + nx];
            float sample[kColour];
            bilinearColour(ex_[m.e], m.x + m.c * dx + m.s * dy, m.y - m.s * dx + m.c * dy, sample);
            const float w = voteWeight_[k];
            for (int c = 0; c < kColour; ++c) acc[c] += w * sample[c];
            weightSum += w;
          }
        float* out = &colour[(static_cast<std::size_t>(y) * t_.w + x) * kColour];
        for (int c = 0; c < kColour; ++c) out[c] = acc[c] / weightSum;
      }
    });
    for (std::size_t i = 0; i < static_cast<std::size_t>(t_.w) * t_.h; ++i)
      std::copy_n(&colour[i * kColour], kColour, &t_.data[i * kStride]);
  }

 private:
  static void bilinearColour(const ExemplarLevel& e, float x, float y, float* out) {
    x = std::clamp(x, 0.0f, e.w - 1.0f);
    y = std::clamp(y, 0.0f, e.h - 1.0f);
    const int x0 = std::min(static_cast<int>(x), e.w - 2 < 0 ? 0 : e.w - 2);
    const int y0 = std::min(static_cast<int>(y), e.h - 2 < 0 ? 0 : e.h - 2);
    const int x1 = std::min(x0 + 1, e.w - 1), y1 = std::min(y0 + 1, e.h - 1);
    const float fx = x - x0, fy = y - y0;
    const float *a = e.at(x0, y0), *b = e.at(x1, y0), *c = e.at(x0, y1), *d = e.at(x1, y1);
    for (int k = 0; k < kColour; ++k)
      out[k] = (1 - fy) * ((1 - fx) * a[k] + fx * b[k]) + fy * ((1 - fx) * c[k] + fx * d[k]);
  }

  // The patch distance at target pixel (px, py) for exemplar position (qx, qy) turned by (c, s). Stops
  // adding once it exceeds `bound` (the best so far).
  float distance(int px, int py, const ExemplarLevel& e, float qx, float qy, float c, float s,
                 float colourWeight, float bound) const {
    float sum = 0;
    const int first = colourWeight > 0 ? 0 : kColour;
    // Every other row and column of the patch: a third of the work for patches of 11 x 11, and still every
    // feature band and pore row of the patch is seen.
    const int step = r_ >= 3 ? 2 : 1;
    for (int dy = -r_; dy <= r_; dy += step) {
      const int ty = std::clamp(py + dy, 0, t_.h - 1);
      for (int dx = -r_; dx <= r_; dx += step) {
        const int tx = std::clamp(px + dx, 0, t_.w - 1);
        const int ix = std::clamp(static_cast<int>(std::floor(qx + c * dx + s * dy + 0.5f)), 0, e.w - 1);
        const int iy = std::clamp(static_cast<int>(std::floor(qy - s * dx + c * dy + 0.5f)), 0, e.h - 1);
        const float* a = t_.at(tx, ty);
        const float* b = e.at(ix, iy);
        for (int k = first; k < kColour; ++k) {
          const float d = (a[k] - b[k]) * colourWeight;
          sum += d * d;
        }
        for (int k = kColour; k < kStride; ++k) {
          const float d = a[k] - b[k];
          sum += d * d;
        }
      }
      if (sum >= bound) return sum;
    }
    return sum;
  }

  bool tryCandidate(int px, int py, int ei, float qx, float qy, Match& best, float colourWeight) const {
    const ExemplarLevel& e = ex_[ei];
    if (!(qx >= e.minX && qx <= e.maxX && qy >= e.minY && qy <= e.maxY)) return false;
    const int ix = static_cast<int>(qx + 0.5f), iy = static_cast<int>(qy + 0.5f);
    const float phi =
        t_.angle[static_cast<std::size_t>(py) * t_.w + px] - e.angle[static_cast<std::size_t>(iy) * e.w + ix];
    const float c = std::cos(phi), s = std::sin(phi);
    const float d = distance(px, py, e, qx, qy, c, s, colourWeight, best.cost);
    if (d >= best.cost) return false;
    best = Match{ei, qx, qy, c, s, d};
    return true;
  }

  // The current match's cost under this pass's colours and weights (its rotation follows its position).
  void rescore(int x, int y, Match& m, float colourWeight) const {
    const Match old = m;
    m.cost = std::numeric_limits<float>::max();
    if (!tryCandidate(x, y, old.e, old.x, old.y, m, colourWeight)) m = old;
  }

  void propagate(int x, int y, const Match& nb, int stepX, int stepY, Match& m, float colourWeight) const {
    tryCandidate(x, y, nb.e, nb.x + nb.c * stepX + nb.s * stepY, nb.y - nb.s * stepX + nb.c * stepY, m,
                 colourWeight);
  }

  // Barnes et al. 2009 Sec. 3.2: candidates around the best at exponentially shrinking radii.
  void randomSearch(int x, int y, Match& m, Random& random, float colourWeight) const {
    const ExemplarLevel& e = ex_[m.e];
    // Below the coarsest level the field was placed by the level above: the search stays near it (a few
    // patch widths; the global candidates still let it jump), which saves half the distances.
    const float start =
        coarsest_ ? 0.5f * std::max(e.w, e.h) : std::min(0.5f * std::max(e.w, e.h), 4.0f * r_);
    for (float radius = start; radius >= 1.0f; radius *= 0.5f) {
      const float qx = m.x + radius * (2 * random.uniform() - 1),
                  qy = m.y + radius * (2 * random.uniform() - 1);
      tryCandidate(x, y, m.e, qx, qy, m, colourWeight);
    }
    tryGlobal(x, y, m, random, colourWeight);
  }

  // A candidate anywhere in any exemplar: lets the field move to another photo.
  void tryGlobal(int x, int y, Match& m, Random& random, float colourWeight) const {
    const int ei = static_cast<int>(random.next() % ex_.size());
    const ExemplarLevel& e = ex_[ei];
    tryCandidate(x, y, ei, e.minX + random.uniform() * (e.maxX - e.minX),
                 e.minY + random.uniform() * (e.maxY - e.minY), m, colourWeight);
  }

  const std::vector<ExemplarLevel>& ex_;
  Level& t_;
  const GuidedSynthesisOptions& o_;
  int level_, r_;
  bool coarsest_;
  std::vector<float> voteWeight_;
  std::vector<Match> nnf_;
};

}  // namespace

Image synthesizeGuided(const std::vector<Exemplar>& exemplars, const SurfaceGuidance& target,
                       const GuidedSynthesisOptions& options, const Progress& progress) {
  if (exemplars.empty()) throw InputError("photo-true appearance: no photo to take the texture from");
  if (options.patchRadius < 1 || options.levels < 1 || options.passes < 1)
    throw InputError("photo-true appearance: patch radius, levels and passes must be at least 1");
  const int r = options.patchRadius;
  // The pyramids; a level is used only while every exemplar still has room for turned patches.
  std::vector<std::vector<ExemplarLevel>> exLevels;
  std::vector<SurfaceGuidance> exGuidance;
  std::vector<Image> exColour;
  for (const Exemplar& e : exemplars) {
    if (e.colour.width != e.guidance.width || e.colour.height != e.guidance.height)
      throw InputError("photo-true appearance: a photo and its guidance differ in size");
    exGuidance.push_back(e.guidance);
    exColour.push_back(e.colour);
  }
  std::vector<SurfaceGuidance> targetLevels{target};
  for (int level = 0; level < options.levels; ++level) {
    std::vector<ExemplarLevel> these;
    const float reach = std::ceil(r * std::sqrt(2.0f)) + 1.0f;
    bool usable = true;
    for (std::size_t i = 0; i < exemplars.size(); ++i) {
      ExemplarLevel e;
      static_cast<Level&>(e) = levelFrom(&exColour[i], exGuidance[i]);
      const float margin = std::ceil(float(exemplars[i].marginPx) / float(1 << level)) + reach;
      e.minX = margin, e.minY = margin, e.maxX = e.w - 1 - margin, e.maxY = e.h - 1 - margin;
      usable = usable && e.usable();
      these.push_back(std::move(e));
    }
    if (!usable) {
      if (level == 0) throw InputError("photo-true appearance: a photo is too small for the patches");
      break;
    }
    exLevels.push_back(std::move(these));
    if (level + 1 < options.levels) {
      for (std::size_t i = 0; i < exemplars.size(); ++i) {
        exGuidance[i] = halveGuidance(exGuidance[i]);
        exColour[i] = halveImage(exColour[i]);
      }
      targetLevels.push_back(halveGuidance(targetLevels.back()));
    }
  }
  const int levels = static_cast<int>(exLevels.size());
  const int totalPasses = levels * options.passes;
  std::vector<Match> coarse;
  int coarseW = 0, coarseH = 0;
  Level result;
  for (int level = levels - 1; level >= 0; --level) {
    Level t = levelFrom(nullptr, targetLevels[level]);
    const bool coarsest = level == levels - 1;
    Synthesis synthesis(exLevels[level], t, options, level, coarsest);
    if (coarsest) {
      synthesis.initialiseRandom();
    } else {
      synthesis.initialiseFrom(coarse, coarseW, coarseH);
      synthesis.vote();
    }
    for (int pass = 0; pass < options.passes; ++pass) {
      progress.throwIfCancelled();
      // The coarsest level's first pass has no colour estimate yet: the guidance alone.
      synthesis.pass(pass, coarsest && pass == 0 ? 0.0f : options.colourWeight);
      const int done = (levels - 1 - level) * options.passes + pass + 1;
      progress.set(double(done) / totalPasses);
    }
    // The last estimate: every pixel from its own match, which keeps the photos' sharpness (the vote's
    // average of slightly shifted patches blurs pores and ring edges); the passes made neighbouring matches
    // coherent, so this is mostly whole patches side by side.
    if (level == 0 && options.sharpFinal) synthesis.vote(true);
    coarse = std::move(synthesis.field());
    coarseW = t.w, coarseH = t.h;
    if (level == 0) result = std::move(t);
  }
  Image out(result.w, result.h, 3);
  for (int y = 0; y < result.h; ++y)
    for (int x = 0; x < result.w; ++x) std::copy_n(result.at(x, y), kColour, out.pixel(x, y));
  return out;
}

}  // namespace kerf
