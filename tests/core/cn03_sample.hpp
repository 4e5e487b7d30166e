#pragma once
// The Mokume cube CN03 of shared/data (U-Net ring maps and face photos) as a growth-field fit's input, for
// the tests that fit it. KERF_SHARED_DIR comes from the test's CMake target; the sample may be absent.
#include <filesystem>
#include <string>

#include "fit/growth_field_fit.hpp"
#include "fit/iso_contours.hpp"
#include "io/image.hpp"

namespace kerf::testing {

inline std::filesystem::path cn03Folder() {
  return std::filesystem::path(KERF_SHARED_DIR) / "data" / "mokume" / "CN03";
}

inline bool cn03Available() {
  return std::filesystem::is_directory(cn03Folder());
}

// The six faces' ring-localization images (X_arl-unet.png) and photos (X_col.png).
inline GrowthFieldFitInput cn03FitInput() {
  GrowthFieldFitInput input;
  for (FaceId f : kAllFaces) {
    const std::string letter(1, faceLetter(f));
    input.rings[faceIndex(f)] = readRingLocalizationImage(cn03Folder() / (letter + "_arl-unet.png"));
    input.photos[faceIndex(f)] = readImage(cn03Folder() / (letter + "_col.png"));
  }
  return input;
}

}  // namespace kerf::testing
