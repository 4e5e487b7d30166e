#include "geometry/face_set.hpp"

#include <bit>

#include "util/error.hpp"

namespace kerf {

int FaceSet::size() const {
  return std::popcount(static_cast<unsigned>(bits_));
}

std::string FaceSet::letters() const {
  std::string out;
  for (FaceId face : kAllFaces)
    if (contains(face)) out += faceLetter(face);
  return out;
}

FaceSet parseFaceSet(std::string_view text) {
  FaceSet faces;
  for (char c : text) {
    if (c == ',' || c == ' ') continue;
    const std::optional<FaceId> face = faceFromLetter(c);
    if (!face)
      throw InputError("'" + std::string(1, c) + "' in \"" + std::string(text) +
                       "\" is not a face letter (faces are A..F)");
    faces.insert(*face);
  }
  return faces;
}

}  // namespace kerf
