#include "fit/held_out_faces.hpp"

#include <algorithm>
#include <cctype>

#include "fit/growth_field_fit.hpp"
#include "util/error.hpp"

namespace kerf {

GrowthFieldFitInput withoutHeldOutFaces(const GrowthFieldFitInput& input) {
  requireFaceLeftToFit(input.heldOut);
  GrowthFieldFitInput kept = input;
  kept.heldOut = {};
  clearFaces(kept.rings, input.heldOut);
  clearFaces(kept.photos, input.heldOut);
  eraseOnFaces(kept.traces, input.heldOut);  // a trace drawn on a photo is derived from it
  eraseOnFaces(kept.knotMarks, input.heldOut);
  return kept;
}

WoodParameters withNeutralTints(WoodParameters params, const FaceSet& heldOut) {
  const WoodParameters defaults;
  for (FaceId face : kAllFaces) {
    if (!heldOut.contains(face)) continue;
    const std::string id = std::string("faces.tint_") +
                           static_cast<char>(std::tolower(static_cast<unsigned char>(faceLetter(face))));
    const std::size_t index = parameterIndex(id).value();  // the schema has a tint per face
    std::ranges::copy(defaults.components(index), params.components(index).begin());
  }
  return params;
}

void requireFaceLeftToFit(const FaceSet& heldOut) {
  if (heldOut.all())
    throw InputError("all six faces are held out (" + heldOut.letters() +
                     "); hold out at most five, so that some face is left to fit");
}

std::string heldOutReportLine(const FaceSet& heldOut) {
  const std::string letters = heldOut.letters();
  std::string list;
  for (char c : letters) list += std::string(list.empty() ? "" : ", ") + c;
  return std::string("held out (leave-one-face-out): face") + (letters.size() > 1 ? "s " : " ") + list +
         "; nothing of " + (letters.size() > 1 ? "their photos" : "its photo") +
         " (ring image, traces, knot marks, colours, texture) is used, so " +
         (letters.size() > 1 ? "their renderings are predictions" : "its rendering is a prediction");
}

}  // namespace kerf
