#include "io/mokume_annotation_files.hpp"

#include <algorithm>
#include <string>

#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "util/error.hpp"

namespace kerf {
namespace fs = std::filesystem;

GrayImage8 readGrayImage8(const fs::path& path) {
  return toGray8(readImage(path, true));
}

void writeGrayImage8(const fs::path& path, const GrayImage8& image) {
  Image out(image.width, image.height, 1);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) out.pixels[i] = image.pixels[i] / 255.0f;
  writeImage(path, out, 8);
}

bool MokumeAnnotationFiles::any() const {
  for (int i = 0; i < 6; ++i)
    if (!rings[i].empty() || !knots[i].empty()) return true;
  return false;
}

MokumeAnnotationFiles findMokumeAnnotationFiles(const fs::path& folder) {
  MokumeAnnotationFiles files;
  for (FaceId face : kAllFaces) {
    const std::string letter(1, faceLetter(face));
    for (const char* ext : {".png", ".tif", ".tiff", ".PNG"}) {
      const fs::path ring = folder / (letter + kMokumeRingSuffix + ext);
      const fs::path knot = folder / (letter + kMokumeKnotSuffix + ext);
      if (files.rings[faceIndex(face)].empty() && fs::exists(ring)) files.rings[faceIndex(face)] = ring;
      if (files.knots[faceIndex(face)].empty() && fs::exists(knot)) files.knots[faceIndex(face)] = knot;
    }
  }
  return files;
}

Annotations readMokumeAnnotations(const MokumeAnnotationFiles& files, const Block& block) {
  Annotations out;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    if (!files.rings[i].empty()) {
      const GrayImage8 image = readGrayImage8(files.rings[i]);
      // Ring lines are thin strokes on a background of 255. Without one, every pixel becomes a ring of
      // its value and the "traces" are the skeleton of the whole face: an inverted or unrelated image.
      const auto background = std::count(image.pixels.begin(), image.pixels.end(), std::uint8_t{255});
      if (2 * static_cast<std::size_t>(background) < image.pixels.size()) {
        throw InputError(files.rings[i].string() + " has no background: " +
                         std::to_string(100 * background / std::max<std::size_t>(1, image.pixels.size())) +
                         " % of its pixels are 255, but a ring image holds thin lines (the year) on 255");
      }
      auto traces = ringTracesFromImage(image, face, block);
      out.traces.insert(out.traces.end(), traces.begin(), traces.end());
    }
    if (!files.knots[i].empty()) {
      for (KnotMark mark : knotMarksFromImage(readGrayImage8(files.knots[i]), face, block)) {
        mark.knot = static_cast<int>(out.knots.size()) / 2;
        out.knots.push_back(mark);
      }
    }
  }
  return out;
}

std::vector<fs::path> writeMokumeAnnotations(const Annotations& annotations, const Block& block,
                                             const fs::path& folder, const std::array<glm::ivec2, 6>& sizes) {
  std::vector<fs::path> written;
  createOutputFolder(folder);
  for (FaceId face : kAllFaces) {
    const std::string letter(1, faceLetter(face));
    const glm::ivec2 size = sizes[faceIndex(face)];
    if (size.x <= 0 || size.y <= 0) throw InputError("no image size for face " + letter);
    const bool numbered = std::any_of(annotations.traces.begin(), annotations.traces.end(),
                                      [&](const RingTrace& t) { return t.face == face && t.year; });
    if (numbered) {
      const fs::path path = folder / (letter + kMokumeRingSuffix + ".png");
      writeGrayImage8(path, ringImageFromTraces(annotations, face, block, size));
      written.push_back(path);
    }
    const bool knots = std::any_of(annotations.knots.begin(), annotations.knots.end(),
                                   [&](const KnotMark& k) { return k.face == face; });
    if (knots) {
      const fs::path path = folder / (letter + kMokumeKnotSuffix + ".png");
      writeGrayImage8(path, knotImageFromMarks(annotations, face, block, size));
      written.push_back(path);
    }
  }
  return written;
}

}  // namespace kerf
