#include "appearance/project_render.hpp"

#include "appearance/photo_true_appearance.hpp"
#include "appearance/photo_true_source.hpp"
#include "io/project.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"

namespace kerf {

std::array<Image, 6> renderProjectFaces(const Project& project, const WoodModel& model, float pxPerMm,
                                        int samples, const Progress& progress) {
  if (project.appearance != Appearance::Photo) return renderFaces(model, pxPerMm, samples, progress);
  const PhotoTrueAppearance appearance(model, loadAppearancePhotos(project), project.heldOutFaces,
                                       photoTrueOptionsFor(model), progress.part(0.0, 0.05));
  return appearance.renderFaces(pxPerMm, progress.part(0.05, 1.0));
}

Image renderProjectCut(const Project& project, const WoodModel& model, const CutPlane& plane, float pxPerMm,
                       int samples, const Progress& progress) {
  if (project.appearance != Appearance::Photo) return renderCut(model, plane, pxPerMm, samples, progress);
  const PhotoTrueAppearance appearance(model, loadAppearancePhotos(project), project.heldOutFaces,
                                       photoTrueOptionsFor(model), progress.part(0.0, 0.1));
  return appearance.renderCut(plane, pxPerMm, progress.part(0.1, 1.0));
}

}  // namespace kerf
