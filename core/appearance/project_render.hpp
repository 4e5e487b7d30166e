#pragma once
// Faces and cuts of a project in the appearance it stores (Project::appearance): the procedural model's
// renderers (render/renderers.hpp) or the photo-true appearance (appearance/photo_true_appearance.hpp),
// made from the project's own photos without its held-out faces.
#include <array>

#include "geometry/cut_plane.hpp"
#include "io/image.hpp"
#include "util/progress.hpp"

namespace kerf {

class WoodModel;
struct Project;

// `samples` (points per pixel side) applies to the procedural model; the photo-true appearance averages
// its own pixels over each output pixel.
std::array<Image, 6> renderProjectFaces(const Project& project, const WoodModel& model, float pxPerMm,
                                        int samples, const Progress& progress = {});
Image renderProjectCut(const Project& project, const WoodModel& model, const CutPlane& plane, float pxPerMm,
                       int samples, const Progress& progress = {});

}  // namespace kerf
