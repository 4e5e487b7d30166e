#include "fit/colour_bins.hpp"

#include <array>
#include <cmath>

namespace kerf::colour_fit {

namespace {

// Where each parameter block starts in one flat vector of the 27 parameters.
constexpr int kEarly = 0, kLate = 3, kSapEarly = 6, kSapLate = 9, kSap = 12, kTint = 14, kProfile = 17;
constexpr int kParameters = 27;
constexpr std::array<int, 7> kBlockStart = {kEarly, kLate, kSapEarly, kSapLate, kSap, kTint, kProfile};
constexpr std::array<int, 7> kBlockSize = {3, 3, 3, 3, 2, 3, kProfileSize};
constexpr double kLuminance[3] = {0.299, 0.587, 0.114};

using Gradient = std::array<double, kParameters>;

}  // namespace

bool BinCost::Evaluate(double const* const* p, double* residuals, double** jacobians) const {
  const double *early = p[0], *late = p[1], *sapEarly = p[2], *sapLate = p[3], *sap = p[4], *tint = p[5],
               *profile = p[6];
  const ColourConstants& k = bin_.constants;
  const bool wantJacobian = jacobians != nullptr;
  double sum[3] = {0, 0, 0}, sumY = 0, sumY2 = 0;
  Gradient dSum[3] = {}, dSumY = {}, dSumY2 = {};
  for (const Sample* s : bin_.members) {
    // Sapwood blend: smoothstep of x = (year - start) / transition + 1/2, flat where clamped.
    double x = (s->year - (sap[0] - 0.5 * sap[1])) / sap[1];
    double dBlendDx = 0;
    if (x < 0) {
      x = 0;
    } else if (x > 1) {
      x = 1;
    } else {
      dBlendDx = 6 * x * (1 - x);
    }
    const double blend = x * x * (3 - 2 * x);
    const double dxDStart = -1 / sap[1], dxDTransition = -(s->year - sap[0]) / (sap[1] * sap[1]);
    double t = s->pigment + profile[8] * s->season;
    for (int i = 0; i < 4; ++i) t += s->profileWeight[i] * profile[(s->profileKnot + 7 + i) % 8];
    const double w = k.rayOpacity * s->ray;
    double colour[3];
    Gradient d[3];
    for (int c = 0; c < 3; ++c) {
      double poreShade = 0, dPoreShade = 0;  // and its derivative in pores.darkness
      for (float pore : s->pore) {
        if (pore > 0.0f) {
          const double a = double(glsl::WoodKernels::kPoreShadow) * pore * k.poreHue[c];
          const double shade = std::exp(-a * profile[9]);
          poreShade += shade, dPoreShade -= a * shade;
        } else {
          poreShade += 1;
        }
      }
      poreShade /= 9.0, dPoreShade /= 9.0;
      const double e = early[c] + blend * (sapEarly[c] - early[c]);
      const double l = late[c] + blend * (sapLate[c] - late[c]);
      const double logRatio = std::log(l / e), power = std::exp(t * logRatio);
      const double beer = e * power * poreShade;
      colour[c] = tint[c] * ((1.0 - w) * beer + w * k.rayColor[c]);
      if (!wantJacobian) continue;
      // beer = e^(1-t) l^t shade: its derivatives in e, l, t and the pores' darkness.
      const double g = tint[c] * (1.0 - w);  // d colour / d beer
      const double dE = beer * (1 - t) / e, dL = beer * t / l;
      const double dBlend = dE * (sapEarly[c] - early[c]) + dL * (sapLate[c] - late[c]);
      Gradient& dc = d[c];
      dc.fill(0.0);
      dc[kEarly + c] = g * dE * (1 - blend);
      dc[kSapEarly + c] = g * dE * blend;
      dc[kLate + c] = g * dL * (1 - blend);
      dc[kSapLate + c] = g * dL * blend;
      dc[kSap + 0] = g * dBlend * dBlendDx * dxDStart;
      dc[kSap + 1] = g * dBlend * dBlendDx * dxDTransition;
      dc[kTint + c] = (1.0 - w) * beer + w * k.rayColor[c];
      const double dT = g * beer * logRatio;
      for (int i = 0; i < 4; ++i) dc[kProfile + (s->profileKnot + 7 + i) % 8] += dT * s->profileWeight[i];
      dc[kProfile + 8] = dT * s->season;
      dc[kProfile + 9] = g * e * power * dPoreShade;
    }
    const double y = kLuminance[0] * colour[0] + kLuminance[1] * colour[1] + kLuminance[2] * colour[2];
    for (int c = 0; c < 3; ++c) sum[c] += colour[c];
    sumY += y, sumY2 += y * y;
    if (!wantJacobian) continue;
    for (int i = 0; i < kParameters; ++i) {
      const double dy = kLuminance[0] * d[0][i] + kLuminance[1] * d[1][i] + kLuminance[2] * d[2][i];
      for (int c = 0; c < 3; ++c) dSum[c][i] += d[c][i];
      dSumY[i] += dy, dSumY2[i] += 2 * y * dy;
    }
  }
  const double n = static_cast<double>(bin_.members.size());
  for (int c = 0; c < 3; ++c) residuals[c] = bin_.weight * (sum[c] / n - bin_.target[c]);
  const double mean = sumY / n, variance = sumY2 / n - mean * mean;
  const double spread = std::sqrt(variance + 1e-8);
  const double spreadScale = bin_.weight * bin_.spreadWeight;
  residuals[3] = spreadScale * (spread - bin_.targetSpread);
  if (!wantJacobian) return true;
  for (std::size_t block = 0; block < kBlockStart.size(); ++block) {
    double* jacobian = jacobians[block];
    if (jacobian == nullptr) continue;  // a block held constant
    const int size = kBlockSize[block];
    for (int j = 0; j < size; ++j) {
      const int i = kBlockStart[block] + j;
      for (int c = 0; c < 3; ++c) jacobian[c * size + j] = bin_.weight * dSum[c][i] / n;
      const double dVariance = dSumY2[i] / n - 2 * mean * dSumY[i] / n;
      jacobian[3 * size + j] = spreadScale * dVariance / (2 * spread);
    }
  }
  return true;
}

}  // namespace kerf::colour_fit
