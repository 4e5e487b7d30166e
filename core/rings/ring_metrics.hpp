#pragma once
// Measuring ring localization: ring pixels of an ARL image, the true ring pixels of a model's face,
// and the agreement of two sets of ring pixels within a distance (docs/rings.md).
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geometry/block.hpp"
#include "image/image.hpp"

namespace kerf {

class WoodModel;

// The ridge lines of a ring-localization image: pixels with value >= threshold that are a maximum
// across the ridge (the direction of strongest negative curvature, from the Hessian of the slightly
// smoothed image). Works for any ARL (Kerf's detector, the Mokume U-Net). 1 channel, 0 or 1.
Image ringRidgePixels(const Image& arl, float threshold = 0.5f);

// The true ring boundary pixels of face `face` of `model` rendered at `size`: where
// year - growth.ring_offset (WoodMaterial::year at the pixel centres) crosses a whole number between
// two 4-neighbours, the one of the two nearer to the crossing is marked. 1 channel, 0 or 1.
Image trueRingPixels(const WoodModel& model, FaceId face, glm::ivec2 size);

// The same for any field of years on a planar grid: pixel (x, y) lies at origin + (x + 0.5) du +
// (y + 0.5) dv (block mm); rings where years - offset crosses a whole number. With compareRingPixels'
// precision at 2 mm this is the accuracy of the learned-inference paper (Table 1): the share of
// predicted ring-line pixels within 2 mm of the true ones.
Image ringLinePixels(const std::function<double(glm::vec3)>& years, double offset, glm::vec3 origin,
                     glm::vec3 du, glm::vec3 dv, glm::ivec2 size);

struct RingAgreement {
  double precision = 0;  // share of detected pixels within the tolerance of a reference pixel
  double recall = 0;     // share of reference pixels within the tolerance of a detected pixel
  long detectedPixels = 0, referencePixels = 0;
  double f1() const { return precision + recall > 0 ? 2 * precision * recall / (precision + recall) : 0; }
};

// Masks: 1-channel images (> 0.5 = ring pixel) of the same size; throws InputError otherwise.
RingAgreement compareRingPixels(const Image& detected, const Image& reference, float tolerancePx);

}  // namespace kerf
