#pragma once
// Leave-one-face-out (issue 16 item 4): what holding a face out of a fit means, in one place. A held-out
// face's photo and everything derived from it - its ring-localization image, the ring traces and knot
// marks drawn on it - are dropped before any stage reads them, and its colour multiplier is reset to
// neutral (an earlier fit may have learned it from that photo). Its rendering is then a prediction.
// The growth-field fit (fit/growth_field_fit.hpp) and the texture inference (texture/texture_inference.hpp)
// apply it to their inputs; callers only pass the set (Project::heldOutFaces).
#include <string>

#include "geometry/face_set.hpp"
#include "params/parameter_schema.hpp"

namespace kerf {

struct GrowthFieldFitInput;

// The input without anything of the held-out faces (input.heldOut); heldOut itself is cleared.
// InputError when every face is held out.
GrowthFieldFitInput withoutHeldOutFaces(const GrowthFieldFitInput& input);

// `params` with faces.tint_<face> at its default for every held-out face.
WoodParameters withNeutralTints(WoodParameters params, const FaceSet& heldOut);

// InputError unless at least one face is left to fit.
void requireFaceLeftToFit(const FaceSet& heldOut);

// The report line of a fit that held faces out ("held out (leave-one-face-out): face C ...").
std::string heldOutReportLine(const FaceSet& heldOut);

}  // namespace kerf
