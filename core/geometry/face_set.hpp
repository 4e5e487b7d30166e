#pragma once
// A set of block faces, written as their letters in A..F order ("AC"). Kerf uses it for the faces held
// out of a fit (leave-one-face-out, issue 16 item 4: Project::heldOutFaces): everything derived from a
// held-out face's photo - the photo, its ring-localization image, ring traces and knot marks drawn on
// it - is dropped where the inputs of a fit are assembled, so the rendered face is a prediction.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/block.hpp"

namespace kerf {

class FaceSet {
 public:
  FaceSet() = default;
  void insert(FaceId face) { bits_ = static_cast<std::uint8_t>(bits_ | bit(face)); }
  bool contains(FaceId face) const { return (bits_ & bit(face)) != 0; }
  bool empty() const { return bits_ == 0; }
  int size() const;
  bool all() const { return size() == 6; }
  FaceSet& operator|=(FaceSet other) {
    bits_ = static_cast<std::uint8_t>(bits_ | other.bits_);
    return *this;
  }
  std::string letters() const;  // "AC"; "" when empty
  bool operator==(const FaceSet&) const = default;

 private:
  static std::uint8_t bit(FaceId face) { return static_cast<std::uint8_t>(1u << faceIndex(face)); }
  std::uint8_t bits_ = 0;
};

// Face letters, any case, optionally separated by commas or spaces ("AC", "a,c"). Throws InputError
// naming the first character that is not a face letter (A..F). An empty text is the empty set.
FaceSet parseFaceSet(std::string_view text);

// Drops what belongs to the faces in `faces`: per-face entries A..F are reset to empty...
template <typename T>
void clearFaces(std::array<T, 6>& perFace, const FaceSet& faces) {
  for (FaceId face : kAllFaces)
    if (faces.contains(face)) perFace[faceIndex(face)] = T{};
}

// ...and items with a `face` member (ring traces, knot marks) on them are erased.
template <typename T>
void eraseOnFaces(std::vector<T>& items, const FaceSet& faces) {
  std::erase_if(items, [&](const T& item) { return faces.contains(item.face); });
}

}  // namespace kerf
