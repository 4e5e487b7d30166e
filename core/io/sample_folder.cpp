#include "io/sample_folder.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "io/image.hpp"
#include "io/input_file.hpp"
#include "io/json_file.hpp"
#include "util/error.hpp"

namespace kerf {
namespace fs = std::filesystem;

namespace {

std::string name(const fs::path& path) {
  return path.filename().string();
}

std::string sizeText(glm::ivec2 size) {
  return std::to_string(size.x) + " x " + std::to_string(size.y) + " px";
}

std::string mmText(float v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

glm::ivec2 readableSize(const fs::path& path, const std::string& what) {
  try {
    const glm::ivec2 size = readImageSize(path);
    if (size.x <= 0 || size.y <= 0) throw InputError("the image is empty");
    return size;
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (" + what + ")");
  }
}

// The block axis (0 = x, 1 = y, 2 = z) along a face's image columns (0) or rows (1).
int axisOf(FaceId face, int direction) {
  const FaceFrame frame = Block().face(face);
  const glm::vec3 d = direction == 0 ? frame.right : frame.down;
  for (int a = 0; a < 3; ++a)
    if (std::abs(d[a]) > 0.5f) return a;
  return 0;
}

bool sameProportions(glm::ivec2 size, glm::vec2 mm) {
  // Pixels along the width the face's proportions give for this height; within 2 % or a pixel.
  const double expected = size.y * static_cast<double>(mm.x) / mm.y;
  return std::abs(size.x - expected) <= std::max(1.0, 0.02 * expected);
}

}  // namespace

std::optional<glm::vec3> readSampleBlockSize(const fs::path& folder) {
  const fs::path file = folder / "block.json";
  if (!fs::exists(file)) return std::nullopt;
  nlohmann::json json;
  try {
    json = parseJsonText(readInputFile(file, "block size file", kMaxJsonFileBytes), file.string());
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (expected {\"size_mm\": [x, y, z]})");
  }
  const auto bad = [&] {
    return InputError(file.string() + ": \"size_mm\" must be three positive lengths in mm, [x, y, z]");
  };
  if (!json.is_object() || !json.contains("size_mm") || !json["size_mm"].is_array() ||
      json["size_mm"].size() != 3)
    throw bad();
  glm::vec3 size(0.0f);
  for (int i = 0; i < 3; ++i) {
    if (!json["size_mm"][i].is_number()) throw bad();
    const double side = json["size_mm"][i].get<double>();
    if (!std::isfinite(side) || side <= 0 || side > std::numeric_limits<float>::max()) throw bad();
    size[i] = static_cast<float>(side);
  }
  return size;
}

std::array<fs::path, 6> findSampleFacePhotos(const fs::path& folder) {
  std::array<fs::path, 6> photos;
  for (FaceId face : kAllFaces)
    for (const char* ext : {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".PNG", ".JPG"}) {
      const fs::path candidate = folder / (std::string(1, faceLetter(face)) + "_col" + ext);
      if (fs::exists(candidate)) {
        photos[faceIndex(face)] = fs::absolute(candidate).lexically_normal();
        break;
      }
    }
  return photos;
}

void validateSampleFolder(const std::array<fs::path, 6>& photos, const MokumeAnnotationFiles& annotations,
                          const Block& block, bool blockFromFile) {
  std::array<glm::ivec2, 6> sizes{};
  const glm::vec3 blockSize = block.size();
  const bool cube = blockSize.x == blockSize.y && blockSize.y == blockSize.z;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    if (photos[i].empty()) continue;
    sizes[i] = readableSize(photos[i], std::string("the photo of face ") + faceLetter(face));
    const glm::vec2 mm = faceSizeMm(block, face);
    if (sameProportions(sizes[i], mm)) continue;
    if (cube) {
      throw InputError(
          std::string("face ") + faceLetter(face) + " photo " + name(photos[i]) + " is " +
          sizeText(sizes[i]) + ", not square, but the block is a " + mmText(blockSize.x) + " mm cube" +
          (blockFromFile ? std::string()
                         : " (a sample folder is Mokume's 40 mm cube unless it holds a block.json "
                           "with {\"size_mm\": [x, y, z]})"));
    }
    throw InputError(name(photos[i]) + " is " + sizeText(sizes[i]) + " but face " + faceLetter(face) +
                     " of the " + mmText(blockSize.x) + " x " + mmText(blockSize.y) + " x " +
                     mmText(blockSize.z) + " mm block is " + mmText(mm.x) + " x " + mmText(mm.y) +
                     " mm: the proportions differ");
  }
  // Along each block axis every face that spans it has the same number of pixels.
  static const char* axisNames[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    std::optional<FaceId> first;
    int firstPx = 0;
    for (FaceId face : kAllFaces) {
      const int i = faceIndex(face);
      if (photos[i].empty()) continue;
      for (int direction = 0; direction < 2; ++direction) {
        if (axisOf(face, direction) != axis) continue;
        const int px = direction == 0 ? sizes[i].x : sizes[i].y;
        if (!first) {
          first = face;
          firstPx = px;
        } else if (px != firstPx) {
          throw InputError(
              name(photos[i]) + " is " + sizeText(sizes[i]) + " but " + name(photos[faceIndex(*first)]) +
              " is " + sizeText(sizes[faceIndex(*first)]) + ": faces " + faceLetter(*first) + " and " +
              faceLetter(face) + " share the block's " + axisNames[axis] + " axis and must have the same " +
              "number of pixels along it (" + std::to_string(firstPx) + " vs " + std::to_string(px) + ")");
        }
      }
    }
  }
  // Annotation images cover their face.
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    const glm::vec2 mm = faceSizeMm(block, face);
    for (const fs::path& file : {annotations.rings[i], annotations.knots[i]}) {
      if (file.empty()) continue;
      const glm::ivec2 size =
          readableSize(file, std::string("the annotation image of face ") + faceLetter(face));
      const bool mokume256 = size == glm::ivec2(256, 256);
      if (!photos[i].empty() && size != sizes[i] && !mokume256) {
        throw InputError(name(file) + " is " + sizeText(size) + " but the photo " + name(photos[i]) + " is " +
                         sizeText(sizes[i]) + " (an annotation image is 256 x 256 px or the photo's size)");
      }
      if (!mokume256 && !sameProportions(size, mm)) {
        throw InputError(name(file) + " is " + sizeText(size) + " but face " + faceLetter(face) + " is " +
                         mmText(mm.x) + " x " + mmText(mm.y) + " mm: the proportions differ");
      }
    }
  }
}

}  // namespace kerf
