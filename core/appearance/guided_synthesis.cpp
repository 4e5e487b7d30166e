#include "appearance/guided_synthesis.hpp"
#include "util/split_mix.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "appearance/exemplar_pyramids.hpp"
#include "appearance/packed_patches.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

constexpr int kColour = 3;

// The nearest-neighbour field's entry: exemplar, position, rotation (the angle bin that turns the
// exemplar's grain onto the target's) and the patch distance.
struct Match {
  int e = 0;
  float x = 0, y = 0;
  std::uint8_t bin = 0;
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

// Every other row and column of the patch in the distance: a third of the work for patches of 11 x 11,
// and still every feature band and pore row of the patch is seen.
int distanceStep(int radius) {
  return radius >= 3 ? 2 : 1;
}

// Patch centres' sub-pixel positions told apart by the distance (appearance/packed_patches.hpp): whole
// pixels alone lose a good part of the orientation agreement on small images (synthetic block, 64 px
// faces: orient 0.96 -> 0.90 on the slanted cut).
constexpr int kSubPixelPhases = 4;

class Synthesis {
 public:
  Synthesis(const std::vector<ExemplarLevel>& exemplars, TargetLevel& target,
            const GuidedSynthesisOptions& options, const PatchSamples& samples, float colourScale, int level,
            bool coarsest)
      : ex_(exemplars),
        colourScale_(colourScale),
        t_(target),
        o_(options),
        level_(level),
        r_(options.patchRadius),
        coarsest_(coarsest),
        samples_(samples),
        voteSamples_(options.patchRadius, 2, 1),
        targetOffsets_(samples.offsets(target.packed)) {
    const float sigma = 0.5f * r_ + 0.5f;
    for (int k = 0; k < voteSamples_.count(); ++k) {
      const int dx = voteSamples_.dx(k), dy = voteSamples_.dy(k);
      voteWeight_.push_back(std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma)));
    }
    for (int bin = 0; bin < kAngleBins; ++bin) {
      cos_[bin] = std::cos(binAngle(bin));
      sin_[bin] = std::sin(binAngle(bin));
    }
  }

  std::vector<Match>& field() { return nnf_; }

  // Random candidates for every pixel (the coarsest level's start), by the guidance alone.
  void initialiseRandom() {
    distance_ = patchDistanceFor(t_.packed.chunks, false);
    nnf_.assign(static_cast<std::size_t>(t_.w) * t_.h, Match{});
    parallelRows(t_.h, [&](int y) {
      Random random = lineRandom(o_.seed, level_, -1, 0, y);
      for (int x = 0; x < t_.w; ++x) {
        Match& m = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        for (int k = 0; k < 6; ++k) tryGlobal(x, y, m, random);
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
        const float c = cos_[m.bin], s = sin_[m.bin];
        const ExemplarLevel& e = ex_[m.e];
        Match& out = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        out.e = m.e;
        out.x = std::clamp(2 * m.x + 0.5f + c * dx + s * dy, e.minX, e.maxX);
        out.y = std::clamp(2 * m.y + 0.5f - s * dx + c * dy, e.minY, e.maxY);
      }
    });
  }

  // The previous slice's field and colours, carried along the fibre (GuidedSliceSynthesis): each pixel
  // starts from the match of the previous slice's pixel nearest to where its wood lay, moved by the rest
  // of the way (turned as the match is), and its colour estimate is the previous slice's colour there.
  void initialiseCarried(const std::vector<Match>& previous, const std::vector<float>& previousColour,
                         const std::vector<glm::vec2>& carry) {
    nnf_.assign(static_cast<std::size_t>(t_.w) * t_.h, Match{});
    parallelRows(t_.h, [&](int y) {
      for (int x = 0; x < t_.w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * t_.w + x;
        const float cx = std::clamp(carry[i].x, 0.0f, t_.w - 1.0f);
        const float cy = std::clamp(carry[i].y, 0.0f, t_.h - 1.0f);
        const int nx = static_cast<int>(std::lround(cx)), ny = static_cast<int>(std::lround(cy));
        const Match& m = previous[static_cast<std::size_t>(ny) * t_.w + nx];
        const float dx = cx - nx, dy = cy - ny, c = cos_[m.bin], s = sin_[m.bin];
        const ExemplarLevel& e = ex_[m.e];
        Match& out = nnf_[i];
        out.e = m.e;
        out.x = std::clamp(m.x + c * dx + s * dy, e.minX, e.maxX);
        out.y = std::clamp(m.y - s * dx + c * dy, e.minY, e.maxY);
        // The colour estimate: bilinear in the previous slice.
        const int x0 = std::min(static_cast<int>(cx), std::max(t_.w - 2, 0));
        const int y0 = std::min(static_cast<int>(cy), std::max(t_.h - 2, 0));
        const int x1 = std::min(x0 + 1, t_.w - 1), y1 = std::min(y0 + 1, t_.h - 1);
        const float fx = cx - x0, fy = cy - y0;
        auto at = [&](int px, int py, int ch) {
          return previousColour[(static_cast<std::size_t>(py) * t_.w + px) * kColour + ch];
        };
        for (int ch = 0; ch < kColour; ++ch)
          t_.colour[i * kColour + ch] = (1 - fy) * ((1 - fx) * at(x0, y0, ch) + fx * at(x1, y0, ch)) +
                                        fy * ((1 - fx) * at(x0, y1, ch) + fx * at(x1, y1, ch));
      }
    });
    updatePackedColours();
  }

  // One PatchMatch pass (a horizontal sweep with propagation and random search, then a vertical sweep with
  // propagation), then, where the next pass needs the colours, the vote. Without colour: the guidance
  // alone.
  void pass(int passIndex, bool withColour, bool voteAfter) {
    distance_ = patchDistanceFor(t_.packed.chunks, withColour);
    const int dir = passIndex % 2 == 0 ? 1 : -1;
    parallelRows(t_.h, [&](int y) {
      Random random = lineRandom(o_.seed, level_, passIndex, 0, y);
      for (int i = 0; i < t_.w; ++i) {
        const int x = dir > 0 ? i : t_.w - 1 - i;
        Match& m = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        rescore(x, y, m);
        if (x - dir >= 0 && x - dir < t_.w)
          propagate(x, y, nnf_[static_cast<std::size_t>(y) * t_.w + x - dir], dir, 0, m);
        randomSearch(x, y, m, random);
      }
    });
    parallelRows(t_.w, [&](int x) {
      Random random = lineRandom(o_.seed, level_, passIndex, 1, x);
      for (int i = 0; i < t_.h; ++i) {
        const int y = dir > 0 ? i : t_.h - 1 - i;
        Match& m = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        if (y - dir >= 0 && y - dir < t_.h)
          propagate(x, y, nnf_[static_cast<std::size_t>(y - dir) * t_.w + x], 0, dir, m);
        if (coarsest_) tryGlobal(x, y, m, random);  // see randomSearch
      }
    });
    if (voteAfter) vote();
  }

  // Kwatra et al. 2005 Sec. 3 (M step): every pixel's colour is the weighted mean of what the patches
  // covering it say (each patch's pixel the nearest photo pixel of its turned offset).
  void vote() {
    parallelRows(t_.h, [&](int y) {
      for (int x = 0; x < t_.w; ++x) {
        Float4 acc = {0, 0, 0, 0};
        float weightSum = 0;
        for (int k = 0; k < voteSamples_.count(); ++k) {
          const int nx = x - voteSamples_.dx(k), ny = y - voteSamples_.dy(k);
          if (nx < 0 || ny < 0 || nx >= t_.w || ny >= t_.h) continue;
          const Match& m = nnf_[static_cast<std::size_t>(ny) * t_.w + nx];
          int ix, iy;
          voteSamples_.phase(m.x, ix);
          voteSamples_.phase(m.y, iy);
          const std::int8_t* turned = voteSamples_.turned(m.bin, 0, 0) + 2 * k;
          acc += voteWeight_[k] * packedColour(ex_[m.e], ix + turned[0], iy + turned[1]);
          weightSum += voteWeight_[k];
        }
        float* out = &t_.colour[(static_cast<std::size_t>(y) * t_.w + x) * kColour];
        for (int c = 0; c < kColour; ++c) out[c] = acc[c] / (weightSum * colourScale_);
      }
    });
    updatePackedColours();
  }

  // Every pixel's colour from its own match alone (bilinear at the match's position).
  void copyMatches() {
    parallelRows(t_.h, [&](int y) {
      for (int x = 0; x < t_.w; ++x) {
        const Match& m = nnf_[static_cast<std::size_t>(y) * t_.w + x];
        bilinearColour(ex_[m.e], m.x, m.y, &t_.colour[(static_cast<std::size_t>(y) * t_.w + x) * kColour]);
      }
    });
    updatePackedColours();
  }

 private:
  void updatePackedColours() {
    t_.packed.setColours(t_.colour.data(), colourScale_, 1.0f);
    t_.packed.fillPad();
  }

  // An exemplar pixel's colour as packed (chunk 0: times the colour scale).
  static Float4 packedColour(const ExemplarLevel& e, int x, int y) { return toFloat4(*e.packed.at(x, y)); }

  void bilinearColour(const ExemplarLevel& e, float x, float y, float* out) const {
    x = std::clamp(x, 0.0f, e.w - 1.0f);
    y = std::clamp(y, 0.0f, e.h - 1.0f);
    const int x0 = std::min(static_cast<int>(x), e.w - 2 < 0 ? 0 : e.w - 2);
    const int y0 = std::min(static_cast<int>(y), e.h - 2 < 0 ? 0 : e.h - 2);
    const int x1 = std::min(x0 + 1, e.w - 1), y1 = std::min(y0 + 1, e.h - 1);
    const float fx = x - x0, fy = y - y0;
    const Float4 c = (1 - fy) * ((1 - fx) * packedColour(e, x0, y0) + fx * packedColour(e, x1, y0)) +
                     fy * ((1 - fx) * packedColour(e, x0, y1) + fx * packedColour(e, x1, y1));
    for (int k = 0; k < kColour; ++k) out[k] = c[k] / colourScale_;
  }

  // The patch distance at target pixel (px, py) for exemplar position (qx, qy), the patch turned so that
  // the exemplar's grain runs along the target's (appearance/packed_patches.hpp). Stops adding once it
  // exceeds the best so far.
  bool tryCandidate(int px, int py, int ei, float qx, float qy, Match& best) const {
    const ExemplarLevel& e = ex_[ei];
    if (!(qx >= e.minX && qx <= e.maxX && qy >= e.minY && qy <= e.maxY)) return false;
    int ix, iy;
    const int phaseX = samples_.phase(qx, ix), phaseY = samples_.phase(qy, iy);
    // The best's own pixel and phase (propagation in coherent regions proposes it again and again): the
    // same distance, which would not be taken.
    if (ei == best.e && best.cost < std::numeric_limits<float>::max()) {
      int bx, by;
      if (samples_.phase(best.x, bx) == phaseX && samples_.phase(best.y, by) == phaseY && bx == ix &&
          by == iy)
        return false;
    }
    const std::uint8_t bin = static_cast<std::uint8_t>(t_.angle[static_cast<std::size_t>(py) * t_.w + px] -
                                                       e.angle[static_cast<std::size_t>(iy) * e.w + ix]);
    const float d = distance_(t_.packed.at(px, py), targetOffsets_.data(), e.packed.at(ix, iy),
                              samples_.turned(bin, phaseX, phaseY), e.packed.rowPixels * e.packed.chunks,
                              samples_.count(), samples_.perRow(), best.cost);
    if (d >= best.cost) return false;
    best = Match{ei, qx, qy, bin, d};
    return true;
  }

  // The current match's cost under this pass's colours and weights (its rotation follows its position).
  void rescore(int x, int y, Match& m) const {
    const Match old = m;
    m.cost = std::numeric_limits<float>::max();
    if (!tryCandidate(x, y, old.e, old.x, old.y, m)) m = old;
  }

  void propagate(int x, int y, const Match& nb, int stepX, int stepY, Match& m) const {
    const float c = cos_[nb.bin], s = sin_[nb.bin];
    tryCandidate(x, y, nb.e, nb.x + c * stepX + s * stepY, nb.y - s * stepX + c * stepY, m);
  }

  // Barnes et al. 2009 Sec. 3.2: candidates around the best at exponentially shrinking radii.
  void randomSearch(int x, int y, Match& m, Random& random) const {
    const ExemplarLevel& e = ex_[m.e];
    // Below the coarsest level the field was placed by the level above: the search stays near it (a few
    // patch widths), which saves half the distances, and makes no global candidate (CN03 held out, mean
    // over three seeds: orient 0.54 with or without them; they are the candidates read from memory).
    const float start =
        coarsest_ ? 0.5f * std::max(e.w, e.h) : std::min(0.5f * std::max(e.w, e.h), 4.0f * r_);
    // Around the match the search started from (v0 of Barnes et al. 2009 Sec. 3.2), so that all the
    // candidates are known at once and their pixels can be fetched from memory while the first are scored.
    const int ei = m.e;
    const float x0 = m.x, y0 = m.y;
    float qx[32], qy[32];
    int n = 0;
    for (float radius = start; radius >= 1.0f && n < 32; radius *= 0.5f, ++n) {
      qx[n] = x0 + radius * (2 * random.uniform() - 1);
      qy[n] = y0 + radius * (2 * random.uniform() - 1);
      prefetchPatch(e, qx[n], qy[n]);
    }
    for (int i = 0; i < n; ++i) tryCandidate(x, y, ei, qx[i], qy[i], m);
    if (coarsest_) tryGlobal(x, y, m, random);
  }

  // Asks for the rows of the patch at (qx, qy) (unturned: close enough) to be brought into the cache.
  void prefetchPatch(const ExemplarLevel& e, float qx, float qy) const {
    if (!(qx >= e.minX && qx <= e.maxX && qy >= e.minY && qy <= e.maxY)) return;
    const int ix = static_cast<int>(qx), iy = static_cast<int>(qy);
    for (int dy = -r_; dy <= r_; dy += samples_.perRow() > 1 ? 2 : 1) {
      const char* row = reinterpret_cast<const char*>(e.packed.at(ix, iy + dy));
      const std::ptrdiff_t half = static_cast<std::ptrdiff_t>(r_) * e.packed.chunks * sizeof(Short4);
      __builtin_prefetch(row - half);
      __builtin_prefetch(row);
      __builtin_prefetch(row + half);
    }
  }

  // A candidate anywhere in any exemplar: lets the field move to another photo.
  void tryGlobal(int x, int y, Match& m, Random& random) const {
    const int ei = static_cast<int>(random.next() % ex_.size());
    const ExemplarLevel& e = ex_[ei];
    tryCandidate(x, y, ei, e.minX + random.uniform() * (e.maxX - e.minX),
                 e.minY + random.uniform() * (e.maxY - e.minY), m);
  }

  const std::vector<ExemplarLevel>& ex_;
  float colourScale_;
  TargetLevel& t_;
  const GuidedSynthesisOptions& o_;
  int level_, r_;
  bool coarsest_;
  const PatchSamples& samples_;
  PatchSamples voteSamples_;
  std::vector<int> targetOffsets_;
  std::vector<float> voteWeight_;
  float cos_[kAngleBins], sin_[kAngleBins];
  PatchDistanceFunction distance_ = nullptr;
  std::vector<Match> nnf_;
};

// Coarse to fine over the prepared levels (the target's as many).
// `finalField`, where given, receives the finest level's nearest-neighbour field.
Image synthesize(const PreparedExemplars& prepared, std::vector<TargetLevel> targets,
                 const GuidedSynthesisOptions& options, const Progress& progress,
                 std::vector<Match>* finalField = nullptr) {
  if (options.patchRadius != prepared.patchRadius || options.colourWeight != prepared.colourWeight ||
      options.levels < static_cast<int>(prepared.levels.size()))
    throw InputError("photo-true appearance: the photos were prepared with other synthesis options");
  if (options.passes < 1) throw InputError("photo-true appearance: passes must be at least 1");
  const PatchSamples samples(options.patchRadius, distanceStep(options.patchRadius), kSubPixelPhases);
  const int levels = static_cast<int>(prepared.levels.size());
  const int totalPasses = levels * options.passes;
  std::vector<Match> coarse;
  int coarseW = 0, coarseH = 0;
  for (int level = levels - 1; level >= 0; --level) {
    TargetLevel& t = targets[level];
    const bool coarsest = level == levels - 1;
    Synthesis synthesis(prepared.levels[level], t, options, samples, prepared.colourScale, level, coarsest);
    if (coarsest) {
      synthesis.initialiseRandom();
    } else {
      synthesis.initialiseFrom(coarse, coarseW, coarseH);
      synthesis.vote();
    }
    for (int pass = 0; pass < options.passes; ++pass) {
      progress.throwIfCancelled();
      // The last pass's colours are used by nothing: the next level votes its own from the field carried
      // down, and the finest level's final colours are its matches' own (sharpFinal).
      const bool last = pass + 1 == options.passes;
      // The coarsest level's first pass has no colour estimate yet: the guidance alone.
      synthesis.pass(pass, !(coarsest && pass == 0) && options.colourWeight > 0.0f,
                     !last || (level == 0 && !options.sharpFinal));
      const int done = (levels - 1 - level) * options.passes + pass + 1;
      progress.set(double(done) / totalPasses);
    }
    // The last estimate: every pixel from its own match, which keeps the photos' sharpness (the vote's
    // average of slightly shifted patches blurs pores and ring edges); the passes made neighbouring matches
    // coherent, so this is mostly whole patches side by side.
    if (level == 0 && options.sharpFinal) synthesis.copyMatches();
    coarse = std::move(synthesis.field());
    coarseW = t.w, coarseH = t.h;
  }
  if (finalField) *finalField = std::move(coarse);
  Image out(targets[0].w, targets[0].h, 3);
  out.pixels = std::move(targets[0].colour);
  return out;
}

std::uint32_t sliceSeed(std::uint32_t seed, int slice) {
  Random r{(static_cast<std::uint64_t>(seed) << 32) ^ static_cast<std::uint64_t>(slice)};
  r.next();
  return static_cast<std::uint32_t>(r.next());
}

}  // namespace

Image synthesizeGuided(const std::vector<Exemplar>& exemplars, const SurfaceGuidance& target,
                       const GuidedSynthesisOptions& options, const Progress& progress) {
  return synthesizeGuided(*prepareExemplars(exemplars, options), target, options, progress);
}

Image synthesizeGuided(const PreparedExemplars& exemplars, const SurfaceGuidance& target,
                       const GuidedSynthesisOptions& options, const Progress& progress) {
  return synthesize(exemplars, targetLevels(exemplars, target), options, progress);
}

Image synthesizeGuided(const PreparedExemplars& exemplars, int index, const GuidedSynthesisOptions& options,
                       const Progress& progress) {
  return synthesize(exemplars, targetLevels(exemplars, index), options, progress);
}

struct GuidedSliceSynthesis::State {
  std::shared_ptr<const PreparedExemplars> exemplars;
  GuidedSynthesisOptions options;
  int continuationPasses = 1;
  int slice = 0;
  int w = 0, h = 0;
  std::vector<Match> field;   // the previous slice's, at the finest level
  std::vector<float> colour;  // the previous slice's colours (RGB)
};

GuidedSliceSynthesis::GuidedSliceSynthesis(std::shared_ptr<const PreparedExemplars> exemplars,
                                           GuidedSynthesisOptions options, int continuationPasses)
    : state_(std::make_unique<State>()) {
  if (!exemplars) throw InputError("photo-true appearance: no prepared photos for the slices");
  if (continuationPasses < 1) throw InputError("photo-true appearance: passes must be at least 1");
  state_->exemplars = std::move(exemplars);
  state_->options = options;
  state_->continuationPasses = continuationPasses;
}

GuidedSliceSynthesis::~GuidedSliceSynthesis() = default;

Image GuidedSliceSynthesis::next(const SurfaceGuidance& guidance, const std::vector<glm::vec2>& carry,
                                 const Progress& progress) {
  State& s = *state_;
  const PreparedExemplars& prepared = *s.exemplars;
  GuidedSynthesisOptions options = s.options;
  options.seed = sliceSeed(s.options.seed, s.slice);
  Image out(guidance.width, guidance.height, 3);
  if (s.slice == 0) {
    out = synthesize(prepared, targetLevels(prepared, guidance), options, progress, &s.field);
    s.w = guidance.width, s.h = guidance.height;
  } else {
    if (guidance.width != s.w || guidance.height != s.h)
      throw InputError("photo-true appearance: every slice must have the first slice's size");
    if (carry.size() != static_cast<std::size_t>(s.w) * s.h)
      throw InputError("photo-true appearance: a slice's carry must give every pixel a place");
    TargetLevel target = targetLevel(prepared, guidance);
    const PatchSamples samples(options.patchRadius, distanceStep(options.patchRadius), kSubPixelPhases);
    Synthesis synthesis(prepared.levels[0], target, options, samples, prepared.colourScale, 0, false);
    synthesis.initialiseCarried(s.field, s.colour, carry);
    for (int pass = 0; pass < s.continuationPasses; ++pass) {
      progress.throwIfCancelled();
      synthesis.pass(pass, options.colourWeight > 0.0f, false);
      progress.set(double(pass + 1) / s.continuationPasses);
    }
    synthesis.copyMatches();
    s.field = std::move(synthesis.field());
    out.pixels = std::move(target.colour);
  }
  s.colour = out.pixels;
  ++s.slice;
  return out;
}

}  // namespace kerf
