#pragma once
// The six faces of a block cut from a log, rendered as the knot test bed's "photos" (docs/knots.md, "A knot
// test bed cut from the spruce log"): Kerf's log model on the CPU (render/board_renderer.hpp) with the log's
// colour map and the model's own noise (each knot's periodic speed noise around its axis, Larsson et al.
// 2022 Sec. 4.1, and the dead knots' outline noise, Sec. 4.3), plus Gaussian pixel noise standing in
// for the camera's. The log model has no pores, fibres or latewood texture, so these photos are easier
// for the ring detector than real ones.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "field/knot_field.hpp"
#include "image/image.hpp"
#include "render/board_renderer.hpp"

namespace kerf::testing {

// Mokume's photos: 256 px over a 40 mm face.
inline constexpr float kMokumePxPerMm = 6.4f;

struct BlockPhotoOptions {
  float pxPerMm = kMokumePxPerMm;
  float pixelNoise = 0.02f;  // standard deviation of the pixel noise, sRGB 0..1 (0: none)
  std::uint32_t seed = 1;
};

inline std::array<Image, 6> renderLogBlockFaces(const KnotField& field, const WoodColorMap& colours,
                                                const Board& board, const BlockPhotoOptions& options = {}) {
  std::array<Image, 6> photos;
  std::mt19937 rng(options.seed);
  std::normal_distribution<float> noise(0.0f, options.pixelNoise);
  for (FaceId f : kAllFaces) {
    BoardRenderOptions render;
    render.face = f;
    const FaceFrame frame = board.block().face(f);
    render.resolution =
        static_cast<int>(std::lround(options.pxPerMm * std::max(frame.widthMm, frame.heightMm)));
    Image image = renderBoardFace(field, colours, board, render);
    if (options.pixelNoise > 0.0f)
      for (float& v : image.pixels) v = std::clamp(v + noise(rng), 0.0f, 1.0f);
    photos[faceIndex(f)] = std::move(image);
  }
  return photos;
}

}  // namespace kerf::testing
