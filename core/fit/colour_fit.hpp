#pragma once
// Colour initialisation (Mokume Sec. 5.3.1 / A.2.3, the third stage of the authors' fit): given the
// fitted growth field and the texture's detail, the colours of the wood and of each photographed face
// are fitted to the face photos.
//
// Kerf's colour model has the parameters of the one schema (not the authors' free 128-entry colour bar):
// heartwood and sapwood earlywood/latewood colours, the heart-to-sapwood radius and blend, a colour
// multiplier per face (faces.tint_*), and the ring profile (rings.profile_*: extra pigment at eight points
// of the year, the base colour as a function of the growth value of Mokume Sec. 5.3.2) with the weight of
// the latewood season in it (rings.season_shading), and the darkness of the pores' shadow
// (pores.darkness: the bins' spread holds it, and a pore band darker than the photo's made the fit lighten
// the wood around it). Everything else the colour depends on - the pigment concentration t of Beer's law
// (season, ring-to-ring variation, mottling, fibres), the pore and ray weights and the growth time - does
// not depend on these parameters, so it is evaluated once per sample point, and the fit itself (Ceres,
// automatic differentiation) only re-mixes colours: colour = tint_face * mix(E (L/E)^(t + profile(year))
// * exp(-k darkness pore), ray colour, ray opacity * ray), E and L blended from heartwood to sapwood by
// the growth time.
// The fit compares per year-phase statistics (issue 16): the mean colour over bins of points (a face, a
// sixteenth of the year, a five-year band), model against photo, starting from the photos' shade at
// each point of the year. A point-by-point loss rewards lowering the contrast wherever the model's
// detail does not land exactly on the photo's (pores never do; rings a fraction of a millimetre off
// do not), which made the faces one flat beige.
// The face tints and the wood colours trade off (a brighter wood under darker tints looks the same); a
// weak penalty on (tint - 1)^2 fixes that scale, as the authors' 10 * mean(face_cols^2) does beside their
// L1 term.
#include <array>

#include "field/growth_rates.hpp"
#include "geometry/block.hpp"
#include "io/image.hpp"
#include "params/parameter_schema.hpp"
#include "util/progress.hpp"

namespace kerf {

struct ColourFitOptions {
  int samplesPerSide = 80;  // sample points per face side (photo and model at the same point)
  int maxIterations = 50;
  double tintWeight = 0.02;    // only fixes the scale between wood colours and tints
  bool fitSapwood = true;      // the heart-to-sapwood radius and blend (needs both on the faces)
  bool fitRingProfile = true;  // rings.profile_*: the shading within a year (Mokume 5.3.2 base colour)
  double profileSmoothness = 0.02, profileSmallness = 0.005;  // priors on the ring profile's knots
  // Weight of the luminance spread within a bin (the contrast of the detail) beside its mean colour.
  double spreadWeight = 1.0;
  double pigmentHueWeight = 0.3;  // keeps latewood's pigment the hue of the photos' light-to-dark axis
  double heartSapWeight = 0.02;   // heartwood colours follow the sapwood's where the photos show one only
  // Keeps pores.darkness near the species' (the start) in log terms: fitted from the bins alone it ranged
  // from 0 to 0.86 on CN03 as one face or another was held out, and at 0 the pores vanish.
  double poreDarknessWeight = 0.03;
};

struct ColourFitResult {
  WoodParameters params;  // the input with color.* (earlywood, latewood, sapwood pair, sapwood start and
                          // blend), rings.profile_*, rings.season_shading and faces.tint_* replaced
  std::array<double, 6> l1Before{}, l1After{};  // mean |model - photo| per face (colour units, 0..1);
                                                // 0 where a face has no photo
  int samples = 0;
  int iterations = 0;
  double seconds = 0;
};

// photos: A..F, empty faces are skipped. Throws InputError without any photo, Cancelled on request.
ColourFitResult fitColours(const Block& block, const WoodParameters& params, const GrowthRates& rates,
                           const std::array<Image, 6>& photos, const ColourFitOptions& options = {},
                           const Progress& progress = {});

}  // namespace kerf
