#pragma once
// Guided patch synthesis: an image for a target surface made of the photos' own patches, each taken where
// the photo's guidance features (appearance/guidance_features.hpp) match the target's.
//
// The method, per pyramid level from coarse to fine (Hertzmann et al. 2001, "Image analogies", Sec. 3.2:
// texture by numbers):
//  - a nearest-neighbour field from every target pixel to a photo position, found with PatchMatch
//    (Barnes et al. 2009, Sec. 3: random initialisation, propagation, random search), whose state also
//    holds the rotation that turns the photo's grain direction onto the target's (so a quarter-sawn photo
//    patch can cover a cut whose grain runs at 30 degrees; Barnes et al. 2010 generalise PatchMatch to
//    rotations the same way);
//  - the patch distance is the guidance features' (ring phase weighted most, so the latewood bands land
//    where the field puts them) plus, once there is an estimate, the colours' (coherence);
//  - the colours are then re-estimated by letting every patch vote for the pixels it covers, weighted by
//    a Gaussian around its centre (Kwatra et al. 2005, "Texture optimization", Sec. 3: the E step and the
//    M step alternate);
//  - the field is carried to the next, finer level and refined there (propagation and a search near it:
//    the global candidates are the coarsest level's).
// Made fast (appearance/packed_patches.hpp, exemplar_pyramids.hpp): exemplars packed once in 16-bit fixed
// point, patches turned through offset tables per angle bin, the distance's sum stopped past the best.
// Rows (and, in the vertical propagation sweep, columns) run in parallel; each line is processed in order
// and reads only its own line of the field, with random numbers drawn from (seed, level, pass, line), so the
// result does not depend on the number of threads: deterministic for a seed.
#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <vector>

#include "appearance/guidance_features.hpp"
#include "io/image.hpp"
#include "util/progress.hpp"

namespace kerf {

// A photo with its guidance at its own pixels (same size).
struct Exemplar {
  Image colour;  // RGB
  SurfaceGuidance guidance;
  int marginPx = 3;  // photo edges are often damaged: no pixel this close to the border is copied
};

struct GuidedSynthesisOptions {
  std::uint32_t seed = 1;
  int levels = 2;             // pyramid levels (each halves the resolution)
  int patchRadius = 5;        // patches of (2r+1)^2 pixels at every level
  int passes = 3;             // PatchMatch + vote passes per level
  float colourWeight = 3.0f;  // colour against guidance in the patch distance
  bool sharpFinal = true;     // the final colours from each pixel's own match rather than the vote
};

// The synthesised colours (RGB) at every pixel of `target` (its size). InputError without exemplars or
// with exemplars too small for the patches. Cancellable.
Image synthesizeGuided(const std::vector<Exemplar>& exemplars, const SurfaceGuidance& target,
                       const GuidedSynthesisOptions& options, const Progress& progress = {});

// The exemplars made ready for the synthesis (appearance/exemplar_pyramids.hpp) once, for many surfaces
// synthesised with the same levels, patch radius and colour weight (InputError as synthesizeGuided).
struct PreparedExemplars;
std::shared_ptr<const PreparedExemplars> prepareExemplars(const std::vector<Exemplar>& exemplars,
                                                          const GuidedSynthesisOptions& options);
// The same, freeing each exemplar's photo and guidance as soon as it is packed (less peak memory).
std::shared_ptr<const PreparedExemplars> prepareExemplars(std::vector<Exemplar>&& exemplars,
                                                          const GuidedSynthesisOptions& options);
Image synthesizeGuided(const PreparedExemplars& exemplars, const SurfaceGuidance& target,
                       const GuidedSynthesisOptions& options, const Progress& progress = {});
// Exemplar `index`'s own surface (the guidance it was prepared with), made from all the exemplars.
Image synthesizeGuided(const PreparedExemplars& exemplars, int index, const GuidedSynthesisOptions& options,
                       const Progress& progress = {});

// The slices of a colour volume (issue 17): parallel surfaces one after another, each made coherent with
// the one before along the fibres, in the way video texture synthesis keeps frames coherent (the previous
// frame's field and colours as the next one's start and colour term). The first slice is synthesised as
// any surface. Every later one starts from the previous slice's nearest-neighbour field and colours,
// carried along the fibre, and is refined by PatchMatch passes at the finest level with those colours in
// the distance (GuidedSynthesisOptions::colourWeight). A pore, a ray or a fibre streak found on one slice
// therefore goes on in the next as long as the guidance lets it: pores become tubes along the fibres, rays
// ribbons, and the latewood bands move as the field says. Deterministic for a seed: each slice's random
// numbers come from (seed, slice index).
class GuidedSliceSynthesis {
 public:
  // `continuationPasses`: the passes that refine a carried slice (at least 1).
  GuidedSliceSynthesis(std::shared_ptr<const PreparedExemplars> exemplars, GuidedSynthesisOptions options,
                       int continuationPasses = 1);
  ~GuidedSliceSynthesis();
  GuidedSliceSynthesis(const GuidedSliceSynthesis&) = delete;
  GuidedSliceSynthesis& operator=(const GuidedSliceSynthesis&) = delete;

  // The next slice's colours (RGB at the guidance's size). `carry`: for every pixel (row-major), where in
  // the previous slice, in its pixels, the wood of this pixel lay (the fibre through it, followed back
  // one slice); ignored for the first slice. Every slice must have the first one's size (InputError).
  Image next(const SurfaceGuidance& guidance, const std::vector<glm::vec2>& carry,
             const Progress& progress = {});

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace kerf
