#pragma once
// The colour fit's residual (fit/colour_fit.hpp): the colour model of kernels/wood.glsl's evaluateWood as
// a function of the fitted parameters only, and the per year-phase bin statistics compared with the
// photos'. Two forms of the same residual: `BinResidual`, templated for Ceres' automatic differentiation
// (the reference), and `BinCost`, with its derivatives written out. The fit uses `BinCost`: automatic
// differentiation carried all 27 parameters through every operation at every point and took 70 % of
// `kerf-cli fit` (7 of 10 s on the demo), and 30x that under the sanitizers. A test checks that both
// forms give the same residuals and Jacobians.
#include <ceres/ceres.h>
#include <glm/vec3.hpp>

#include <cmath>
#include <vector>

#include "material/wood_kernels.hpp"

namespace kerf::colour_fit {

// The ring profile's eight knots, rings.season_shading and pores.darkness: the shading of the year and of
// its pores, fitted together because the photos' per-bin spread holds both.
constexpr int kProfileSize = 10;

// What a sample point's colour depends on besides the fitted parameters (fixed during the fit). One
// photo point and the model at that same point: averaging the photo over cells (as an earlier version
// did) mixes earlywood and latewood and pulls the fit to one mean colour (issue 16).
struct Sample {
  int face = 0;
  double pigment = 0;  // Beer's-law concentration t without the ring profile and the season
  double season = 0;   // the season s (0 earlywood, 1 latewood), weighed by rings.season_shading
  double year = 0, ray = 0;
  // The pore weights over the photo pixel's footprint (3 x 3 points): a photo pixel averages a pore
  // smaller than itself, a single model point does not, and that made the fit pale the pores (issue 16).
  // Their shadow's darkness is fitted (profile[9]).
  float pore[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  double phase = 0;     // where in its year the point lies (0 at a ring boundary)
  int profileKnot = 0;  // the ring profile's knots k-1 .. k+2 (mod 8) and their weights here
  double profileWeight[4] = {0, 0, 0, 0};
  double target[3] = {0, 0, 0};  // the photo's colour at the point
};

// What every point of a fit shares: the ray colour and opacity (not fitted), the pores' shadow hue.
struct ColourConstants {
  glm::dvec3 rayColor{0.0};
  double rayOpacity = 0;
  glm::dvec3 poreHue{1.0};  // pores.shadow_hue over its mean (kernels/wood.glsl poreShadeOf)
};

// The colour of one sample point: tint * mix(E (L/E)^t * pore shade, ray colour, ray opacity * ray), with
// E and L blended from heartwood to sapwood by the growth time.
struct ColourModel {
  const Sample* s;
  const ColourConstants* k;

  template <class T>
  void operator()(const T* early, const T* late, const T* sapEarly, const T* sapLate, const T* sap,
                  const T* tint, const T* profile, T* out) const {
    using std::exp;
    using std::log;
    T x = (T(s->year) - (sap[0] - 0.5 * sap[1])) / sap[1];
    if (x < T(0)) x = T(0);
    if (x > T(1)) x = T(1);
    const T blend = x * x * (T(3) - T(2) * x);
    // profile[0..7]: the ring profile's knots; profile[8]: rings.season_shading; profile[9]: pores.darkness.
    T t = T(s->pigment) + profile[8] * s->season;
    for (int i = 0; i < 4; ++i) t += s->profileWeight[i] * profile[(s->profileKnot + 7 + i) % 8];
    const double w = k->rayOpacity * s->ray;
    for (int c = 0; c < 3; ++c) {
      T poreShade(0);  // kernels/wood.glsl's poreShadeOf, averaged over the pixel
      for (float pore : s->pore)
        poreShade += pore > 0.0f
                         ? exp(-double(glsl::WoodKernels::kPoreShadow) * pore * k->poreHue[c] * profile[9])
                         : T(1);
      poreShade /= 9.0;
      const T e = early[c] + blend * (sapEarly[c] - early[c]);
      const T l = late[c] + blend * (sapLate[c] - late[c]);
      const T beer = e * exp(t * log(l / e)) * poreShade;
      out[c] = tint[c] * ((1.0 - w) * beer + w * k->rayColor[c]);
    }
  }
};

// Per year-phase statistics (issue 16): over a bin of points - one face, one sixteenth of the year, one
// band of five years - the model's mean colour and its spread of luminance against the photos' over the
// same points. Point by point, the model's pores and the photo's never line up, and rings a fraction
// of a millimetre off their photo disagree at every edge; the least-squares answer to both is to lower
// the contrast until the faces are one beige. The bin means are what the model can and must match
// point for point: the shade of each part of the year, from heart to sapwood, from face to face. The
// spread within a bin is the contrast of the detail that cannot be aligned (pores, fibres, mottling):
// by Beer's law it grows with the earlywood-latewood colour ratio, which the means alone leave free.
struct Bin {
  std::vector<const Sample*> members;
  ColourConstants constants;
  double weight = 0, spreadWeight = 1;
  double target[3] = {0, 0, 0};
  double targetSpread = 0;  // standard deviation of the photo's luminance over the bin
};

// Residuals: weight * (model mean - photo mean) per channel, then weight * spreadWeight * (model
// luminance spread - photo's). Parameter blocks: early, late, sapEarly, sapLate (3 each), sap (start,
// transition), the face's tint (3), the profile (kProfileSize).
struct BinResidual {
  Bin bin;

  template <class T>
  bool operator()(const T* early, const T* late, const T* sapEarly, const T* sapLate, const T* sap,
                  const T* tint, const T* profile, T* residual) const {
    T sum[3] = {T(0), T(0), T(0)}, sumLuminance(0), sumLuminance2(0);
    for (const Sample* s : bin.members) {
      T colour[3];
      ColourModel{s, &bin.constants}(early, late, sapEarly, sapLate, sap, tint, profile, colour);
      for (int c = 0; c < 3; ++c) sum[c] += colour[c];
      const T y = 0.299 * colour[0] + 0.587 * colour[1] + 0.114 * colour[2];
      sumLuminance += y, sumLuminance2 += y * y;
    }
    const double n = static_cast<double>(bin.members.size());
    for (int c = 0; c < 3; ++c) residual[c] = bin.weight * (sum[c] / n - bin.target[c]);
    using std::sqrt;
    const T variance = sumLuminance2 / n - (sumLuminance / n) * (sumLuminance / n);
    residual[3] = bin.weight * bin.spreadWeight * (sqrt(variance + 1e-8) - bin.targetSpread);
    return true;
  }
};

// The same residual as BinResidual with its Jacobian by hand (the chain rule through the model above).
class BinCost final : public ceres::SizedCostFunction<4, 3, 3, 3, 3, 2, 3, kProfileSize> {
 public:
  explicit BinCost(Bin bin) : bin_(std::move(bin)) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Bin bin_;
};

}  // namespace kerf::colour_fit
