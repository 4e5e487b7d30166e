#include "render/unfolded_cross.hpp"

#include <algorithm>

#include "util/error.hpp"

namespace kerf {

Image unfoldedCross(const std::array<Image, 6>& faces, const Block& block, float background) {
  // Column widths and row heights of the 4 x 3 cross grid, in pixels, from the faces placed in them.
  std::array<int, 4> columnWidth{};
  std::array<int, 3> rowHeight{};
  for (FaceId face : kAllFaces) {
    const Image& image = faces[faceIndex(face)];
    if (image.channels != 3) throw InputError("unfolded cross needs RGB face images");
    const CrossSlot slot = crossSlot(face);
    columnWidth[slot.column] = std::max(columnWidth[slot.column], image.width);
    rowHeight[slot.row] = std::max(rowHeight[slot.row], image.height);
  }
  std::array<int, 5> x0{};
  std::array<int, 4> y0{};
  for (int i = 0; i < 4; ++i) x0[i + 1] = x0[i] + columnWidth[i];
  for (int i = 0; i < 3; ++i) y0[i + 1] = y0[i] + rowHeight[i];
  Image out(x0[4], y0[3], 3);
  std::fill(out.pixels.begin(), out.pixels.end(), background);
  for (FaceId face : kAllFaces) {
    const Image& image = faces[faceIndex(face)];
    const CrossSlot slot = crossSlot(face);
    for (int y = 0; y < image.height; ++y)
      std::copy_n(image.pixel(0, y), image.width * 3, out.pixel(x0[slot.column], y0[slot.row] + y));
  }
  (void)block;
  return out;
}

}  // namespace kerf
