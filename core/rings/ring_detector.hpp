#pragma once
// Automatic ring localization (Mokume Sec. 5.1): a face photo -> a ring-localization image ("ARL") in
// [0, 1] with the meaning of the paper's Eq. 1, I(g) = ((cos(2 pi g) + 1) / 2)^10: 1 on the annual
// ring boundaries, falling to 0 within a small part of a ring on either side.
//
// RingDetector is the interface (a learned model, e.g. a U-Net like the authors', can implement it
// later); ClassicalRingDetector is Kerf's detector built on OpenCV from the structure of wood rather
// than raw gradients (see docs/rings.md):
//
//   1. luminance, grey closing (fills pores and pore grooves), the pore density put back as smooth
//      dark bands, illumination flattening (local mean and contrast normalisation);
//   2. structure tensor -> ring orientation field and coherence; the across-ring normals are given a
//      consistent sign over the face by quality-guided propagation (most coherent pixels first);
//   3. smoothing along the ring direction (oriented Gaussian line filter), which melts pores, rays,
//      fibre streaks and noise into the ring's mean tone, and a little across;
//   4. signed derivative across the rings; non-maximum suppression across the ring direction;
//   5. polarity: of the two edges of each latewood band, the ring boundary (latewood -> next year's
//      earlywood) is the sharp one, so the derivative across a ring is skewed towards the boundary's
//      sign; Auto picks, per face, the sign with the larger third moment;
//   6. hysteresis on the edge strength where the orientation is coherent, long connected curves only;
//   7. output: Eq. 1 profile of the distance to the nearest boundary over the face's ring width.
#include <string>
#include <vector>

#include "image/image.hpp"
#include "util/progress.hpp"

namespace kerf {

class RingDetector {
 public:
  virtual ~RingDetector() = default;
  virtual std::string name() const = 0;
  // `photo`: RGB or grey, values 0..1, covering one face at `pxPerMm` pixels per millimetre.
  // Returns a 1-channel image of the same size with values in [0, 1] (Eq. 1 meaning).
  // Throws InputError for an empty photo, Cancelled when progress.stop is requested.
  virtual Image localize(const Image& photo, float pxPerMm, const Progress& progress = {}) const = 0;
};

struct ClassicalRingParams {
  // Lengths are in millimetres on the wood (converted with pxPerMm), so the detector behaves the same
  // at any photo resolution.
  // Grey closing (structuring disc of this radius) applied to the luminance first: fills dark pores
  // and pore grooves narrower than twice the radius, keeps the wider latewood bands. 0 = off.
  float poreClosingMm = 0.3f;
  // Pore density: what the closing filled (black top-hat), smoothed over poreDensitySigmaMm, is
  // subtracted from the closed luminance with this weight, so bands of pores (the earlywood of
  // ring-porous wood) read as dark bands while single pores and grooves do not. 0 = off.
  float poreContrast = 3.0f;
  float poreDensitySigmaMm = 0.3f;
  float illuminationSigmaMm = 3.0f;  // scale of the background (light falloff, heart/sapwood colour) removed
  float gradientSigmaMm = 0.12f;     // pre-smoothing for the structure tensor's gradients
  float orientationSigmaMm = 2.5f;   // structure tensor integration scale (spans many pores and rays)
  float alongSigmaMm = 0.9f;         // Gaussian smoothing along the rings (pores, rays, noise)
  float acrossSigmaMm = 0.06f;       // Gaussian smoothing across the rings (keep the boundary sharp)
  float derivativeStepMm = 0.12f;    // half-distance of the central difference across the rings
  float minCoherence = 0.15f;        // below: no reliable ring direction, no boundary
  // Edge strengths are differences of contrast-normalised luminance (a clean square wave of unit
  // standard deviation steps by 2).
  float highThreshold = 0.8f;  // a boundary curve must reach this somewhere
  float lowThreshold = 0.18f;  // ... and is followed down to this
  float minLengthMm = 5.0f;    // shorter curves are dropped
  enum class Polarity { Auto, Rising, Falling, Both };
  // Rising/Falling: along the propagated normal (arbitrary per face); only Auto and Both are useful
  // from outside.
  Polarity polarity = Polarity::Auto;
  // Judge Auto's polarity on the luminance before the pore closing (pores show the earlywood side).
  // Measured: worse on CN03 (0.687 / 0.747 against 0.791 / 0.805), same on the synthetic woods; off.
  bool polarityFromUnclosed = false;
  float power = 10.0f;  // exponent of the Eq. 1 profile
  // Ring width bounds for the profile (the width is measured on each face between detected boundaries).
  float minRingWidthMm = 0.6f, maxRingWidthMm = 15.0f;
};

// What the classical detector found on one face, beyond the ARL image.
struct ClassicalRingResult {
  Image arl;           // 1 channel, [0, 1]
  Image boundaries;    // 1 channel, 1 on the detected boundary pixels (1 px wide curves)
  Image coherence;     // 1 channel, [0, 1]
  int chosenSign = 0;  // +1 / -1 along the propagated normal (0 for Polarity::Both)
  // Auto's scores for sign -1 (index 0) and +1 (index 1): shares of the cubed derivative (sum 1).
  float sharpness[2] = {0, 0};
  float ringWidthPx = 0;  // measured ring width used for the profile
};

class ClassicalRingDetector : public RingDetector {
 public:
  explicit ClassicalRingDetector(ClassicalRingParams params = {}) : params_(params) {}
  std::string name() const override { return "classical"; }
  Image localize(const Image& photo, float pxPerMm, const Progress& progress = {}) const override;
  ClassicalRingResult detect(const Image& photo, float pxPerMm, const Progress& progress = {}) const;
  const ClassicalRingParams& params() const { return params_; }

 private:
  ClassicalRingParams params_;
};

}  // namespace kerf
