#pragma once
// The Mokume annotation files of a sample folder (Appendix A.1.2): `<F>_ann.png` ring images and
// `<F>_knot.png` knot images, read into Annotations and written from them. The images' contents are
// rings/annotations.hpp's (ringTracesFromImage, knotImageFromMarks...); this is the file side.
#include <array>
#include <filesystem>
#include <glm/vec2.hpp>
#include <vector>

#include "geometry/block.hpp"
#include "image/gray_image.hpp"
#include "rings/annotations.hpp"

namespace kerf {

// Reading throws InputError naming the file when it cannot be read.
GrayImage8 readGrayImage8(const std::filesystem::path& path);
void writeGrayImage8(const std::filesystem::path& path, const GrayImage8& image);  // PNG, atomically

// The annotation files of a sample folder that exist: `<F>_ann.png` and `<F>_knot.png` (also .tif).
struct MokumeAnnotationFiles {
  std::array<std::filesystem::path, 6> rings, knots;  // empty where absent
  bool any() const;
};
MokumeAnnotationFiles findMokumeAnnotationFiles(const std::filesystem::path& folder);
// Reads them: numbered traces, and knot marks. The marks of all faces are grouped into knots in face
// order A..F, two marks per knot (the first two marks are knot 0, the next two knot 1, ...), as a
// Mokume sample has at most one knot crossing two faces.
Annotations readMokumeAnnotations(const MokumeAnnotationFiles& files, const Block& block);

// Writes `<F>_ann.png` for every face with numbered traces and `<F>_knot.png` for every face with knot
// marks into `folder` (created if needed), each of imageSizes[face] pixels. Returns the files written.
std::vector<std::filesystem::path> writeMokumeAnnotations(const Annotations& annotations, const Block& block,
                                                          const std::filesystem::path& folder,
                                                          const std::array<glm::ivec2, 6>& imageSizes);

}  // namespace kerf
