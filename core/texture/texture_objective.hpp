#pragma once
// The loss the texture inference minimises: for every photographed face, between crops of the rendered
// face and the same crops of its photo, the grain direction agreement and contrast ratio
// (texture/grain_view.hpp), the style distance (texture/texture_statistics.hpp), and a weak L1 colour term
// (Mokume A.2.3 fits colours with L1). Each face is compared with its own
// photo, because what a face shows depends on its orientation to the grain (learned-inference paper
// Sec. 3.3): end grain shows pores as dots and rays as lines across the rings, side grain shows pores
// as grooves and rays as flecks. End-grain and side-grain faces are averaged separately and then
// together, so the two end faces weigh as much as the four side faces: each orientation constrains
// different parameters (pore radius and spacing vs pore length, ray height and fibre length).
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "field/growth_rates.hpp"
#include "fit/ring_band_profile.hpp"
#include "geometry/block.hpp"
#include "io/image.hpp"
#include "params/parameter_schema.hpp"
#include "texture/face_crops.hpp"
#include "texture/grain_view.hpp"
#include "texture/shading_layers.hpp"
#include "texture/texture_statistics.hpp"
#include "util/progress.hpp"

namespace kerf {

struct TextureLossOptions {
  int cropsPerFace = 2;
  int cropSize = 96;  // px, at the photos' own px/mm
  // Points per pixel side. 1 is 2.4 times faster and on CN03 (from the nara preset, 8 sweeps) nearly as
  // good: contrast 1.04, orient 0.69, corr 0.12, style 0.30 in 90 s against 1.01 / 0.71 / 0.13 / 0.29 in
  // 220 s (appearance_eval.py, docs/texture.md); but rays and pores under a pixel wide then alias and the
  // search loses them (the synthetic round trip's ray spacing: 3.9 mm for 0.9).
  int samples = 2;
  std::uint32_t seed = 1;  // where the crops lie
  double l1Weight = 2.0;   // mean |render - photo| (0..1 colour units) is ~0.02-0.1, the style ~0.1-1
  // What a woodworker sees first (texture/grain_view.hpp): weight of (1 - grain direction agreement) and
  // of |log contrast ratio|. Without them the style statistics alone let pores run across the grain and
  // washed the flat-sawn ring figure out (issue 16).
  double grainWeight = 0.5;
  double contrastWeight = 0.5;
  double figureWeight = 1.0;  // of (1 - figure correlation): the ring figure stays where the field put it
  double streakWeight =
      1.0;  // of the streak-length difference (grain_view.hpp): pores as long as the photo's
  // Of the ring-band difference (fit/ring_band_profile.hpp): the dark detail (pores) in the same part
  // of the ring as the photo's, e.g. a band of several rows at the start of the earlywood. Off in the
  // search (0; the report always shows it): on CN03 a weight of 1 made the band no wider. The model ties
  // the earlywood pores' band to the earlywood colour's (1 - rings.latewood_fraction), and the search
  // raised that share with or without the term; with it, it spread the pores over the ring instead
  // (smaller pores, a slower transition) and the faces looked worse (docs/texture.md).
  double bandWeight = 0.0;
  int bandBins = 8;  // parts of the ring for it (about 0.4 mm each on CN03's 3-4 mm rings)
  // Statistics also per part of the ring (ring phase in this many equal parts, from the fitted field), so
  // the loss sees where in the ring pores and latewood sit; 0: pooled over the face only. Off by default:
  // on CN03 three phases did not make the result look closer and made the loss noisier (docs/texture.md).
  int ringPhaseBins = 0;
  TextureStatisticsOptions statistics;
};

struct FaceTextureScore {
  bool used = false;  // the face has a photo
  double style = 0;   // StyleDistance::total
  double l1 = 0;      // mean |render - photo| per channel value, 0..1
  // The same after blurring both images by 1 mm (whole faces only, else 0): the colours and the ring
  // pattern without the detail. Plain L1 grows when pores appear anywhere but exactly where the photo
  // has its own, so it cannot judge detail; this one says whether the colours still match.
  double l1Blurred = 0;
  double grain = 0;     // grain direction agreement with the photo (texture/grain_view.hpp), at most 1
  double contrast = 0;  // band-passed contrast over the photo's (1 the same)
  double figure = 0;    // correlation of the ring figure's light and dark bands with the photo's
  double streak = 0;    // streak-length difference from the photo's (0 the same)
  double band = 0;  // ring-band difference from the photo's (0 the dark detail in the same part of the ring)
};

struct TextureScore {
  double loss = 0;
  std::array<FaceTextureScore, 6> faces;
};

class TextureObjective {
 public:
  // params: the starting parameters: their pith axis (face orientations) and where their field puts each
  // crop point (reused for every candidate that puts them in the same places). Throws InputError
  // (no photos, photos whose proportions differ from their faces).
  TextureObjective(const Block& block, const GrowthRates& rates, const WoodParameters& params,
                   const std::array<Image, 6>& photos, const TextureLossOptions& options = {});

  // Scores of every candidate on the crops, in parallel (over candidates and crops). Cancellable.
  std::vector<TextureScore> evaluate(const std::vector<WoodParameters>& candidates,
                                     const Progress& progress = {}) const;
  // The same loss on whole faces (for reports; slower).
  TextureScore evaluateFullFaces(const WoodParameters& params, const Progress& progress = {}) const;
  // The same for several parameter sets at once: the faces' points located once and the layers that the
  // sets agree on shaded once (texture/shading_layers.hpp); the scores as one by one, bit for bit.
  std::vector<TextureScore> evaluateFullFaces(const std::vector<WoodParameters>& candidates,
                                              const Progress& progress = {}) const;

  // Per face, the photo's mean colour over the crops divided by the rendering's (1 where a face has no
  // photo): the face tint correction that matches the mean colours without touching the texture.
  std::array<glm::vec3, 6> meanColourRatios(const WoodParameters& params,
                                            const Progress& progress = {}) const;

  const FaceCropLayout& layout() const { return layout_; }
  // Points shaded by evaluate() so far: composed, and computed per layer group (shading_layers.hpp).
  const ShadingCounts& shadingCounts() const { return counts_; }
  const std::array<FaceOrientation, 6>& orientations() const { return orientations_; }

 private:
  double combine(const std::array<FaceTextureScore, 6>& faces) const;

  Block block_;
  GrowthRates rates_;
  WoodParameters startParams_;  // its rings give the ring phases
  TextureLossOptions options_;
  std::array<Image, 6> photos_;
  FaceCropLayout layout_;
  std::array<FaceOrientation, 6> orientations_{};
  std::vector<Image> photoCrops_;                                    // layout_.crops order
  std::vector<GrainView> photoGrain_;                                // layout_.crops order
  std::array<std::vector<TextureStatistics>, 6> photoStatistics_{};  // per face: pooled, per ring phase
  std::vector<std::vector<std::uint8_t>> cropLabels_;                // ring phase of each crop pixel
  std::vector<std::vector<std::uint8_t>> bandLabels_;                // the same in options_.bandBins parts
  std::array<RingBandProfile, 6> photoBand_{};                       // per face, over its crops
  std::array<std::vector<std::size_t>, 6> cropsOfFace_{};            // indices into layout_.crops
  // Where every point of every crop lies in the tree under the start parameters (layout_.crops order),
  // shaded again for each candidate whose probe points lie in the same places (sameLocations).
  std::vector<std::vector<WoodLocation>> cropLocations_;
  std::vector<glm::vec3> probes_;
  std::vector<WoodLocation> probeLocations_;
  bool sameLocations(const WoodModel& model) const;
  mutable ShadingCounts counts_;
  Image renderCrop(const WoodModel& model, bool located, std::size_t k) const;
};

}  // namespace kerf
