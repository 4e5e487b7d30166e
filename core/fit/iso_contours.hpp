#pragma once
// Ring contours from a ring-localization image, as the Mokume authors' growth-field step extracts them
// (shared/reference/MOKUME_CONVENTIONS.md section C): threshold the grey image (> 200), take the
// closed pixel boundaries of every bright band (OpenCV findContours, RETR_TREE, CHAIN_APPROX_NONE),
// and cut each closed boundary where it comes within 5 px of the image border, keeping the open
// pieces longer than 32 points. A band crossing the image thus gives two open contours, one per band
// edge; a closed ring inside the image (pith inside the block) is kept whole,
// provided it too has more than 32 points.
//
// The extraction itself is core/rings/contours.hpp (extractContours); this is the fit's 8-bit interface
// to it: the fit only needs lists of pixels per contour.
#include <cstdint>
#include <filesystem>
#include <glm/vec2.hpp>
#include <vector>

#include "image/gray_image.hpp"

#include "geometry/block.hpp"

namespace kerf {

// An 8-bit grey image, row-major, top row first.
// Reads a ring-localization image (e.g. Mokume's X_arl-unet.png) as the authors do: colour images
// give their red channel (all channels are equal in Mokume's images). Throws InputError.
GrayImage8 readRingLocalizationImage(const std::filesystem::path& path);

// The ring-localization image of `face` in a sample folder: X_arl-unet.png (the Mokume authors')
// first, else the first X_arl*.png by name (e.g. Kerf's own X_arl.png); empty when there is none.
std::filesystem::path findRingLocalizationImage(const std::filesystem::path& folder, FaceId face);

struct ContourExtractionOptions {
  int threshold = 200;     // a pixel is on a ring when its grey value is > threshold
  int borderMarginPx = 5;  // points with x <= m, x >= width - m (same for y) are edge points
  int minPoints = 32;      // open pieces need more points than this
};

// The contours as lists of pixel indices (x = column, y = row), in the order OpenCV walks them.
// Deterministic.
std::vector<std::vector<glm::ivec2>> extractIsoContours(const GrayImage8& image,
                                                        const ContourExtractionOptions& options = {});

}  // namespace kerf
