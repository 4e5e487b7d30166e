#pragma once
// Kerf's learned ring detector (issue 18 item 1; docs/rings.md "The learned detector"): a small
// fully-convolutional network trained by the project itself on faces rendered by Kerf's own model
// (bench/ring_training_data.cpp, scripts/train_ring_detector.py), as the learned-inference paper trains
// on procedural data. It maps a face photo to Mokume Eq. 1's ring-localization image, like the authors'
// U-Net (Mokume Sec. 5.1), and learns from the data which edge of a latewood band is the ring boundary.
// The weights ship in resources/models/ring_detector.onnx, compiled into the core; inference runs on
// OpenCV DNN (multithreaded by OpenCV's pool). ClassicalRingDetector stays the fallback and the baseline.
#include <cstddef>
#include <span>
#include <string>

#include "rings/ring_detector.hpp"

namespace kerf {

// The resolution the network was trained at (Mokume's 256 px per 40 mm face): photos are resampled to
// it and the ring image back to the photo's size.
inline constexpr float kLearnedDetectorPxPerMm = 6.4f;

// The shipped network (ONNX bytes), compiled in from resources/models/ring_detector.onnx.
std::span<const std::byte> builtInRingDetectorModel();

// How the network's ring probability becomes the ring-localization image (lengths in mm on the wood).
struct LearnedRingParams {
  // false: localize() returns the network's probability itself (the evidence, e.g. for a fit term).
  bool crisp = true;
  // Ridges of the probability above lowThreshold, kept where a connected ridge reaches highThreshold and
  // is minLengthMm long; then Eq. 1's profile over the measured ring width, as the classical detector.
  float lowThreshold = 0.25f, highThreshold = 0.5f;
  float minLengthMm = 5.0f;
  float smoothMm = 0.3f;  // Gaussian smoothing of the probability first (its pores and pits)
  float minRingWidthMm = 0.6f, maxRingWidthMm = 15.0f;
  float power = 10.0f;
};

class LearnedRingDetector : public RingDetector {
 public:
  // The built-in network.
  explicit LearnedRingDetector(LearnedRingParams params = {});
  // Another network in the same format (ONNX: input 1 x 3 x H x W normalised RGB, output 1 x 1 x H x W
  // in 0..1). Throws InputError naming `what` when it does not load.
  LearnedRingDetector(std::span<const std::byte> onnx, std::string what, LearnedRingParams params = {});
  std::string name() const override { return "learned"; }
  Image localize(const Image& photo, float pxPerMm, const Progress& progress = {}) const override;

 private:
  std::span<const std::byte> model_;
  std::string what_;
  LearnedRingParams params_;
};

// The detector a name asks for ("classical" or "learned"); throws InputError naming the choices otherwise.
const RingDetector& ringDetectorNamed(const std::string& name);

}  // namespace kerf
