#include "appearance/photo_true_source.hpp"

#include "io/project.hpp"
#include "render/wood_model.hpp"

namespace kerf {

std::optional<PhotoTrueSource> photoTrueSourceOf(const Project& project) {
  if (project.appearance != Appearance::Photo) return std::nullopt;
  return PhotoTrueSource{project.facePhotos, project.heldOutFaces};
}

PhotoTrueOptions photoTrueOptionsFor(const WoodModel& model) {
  PhotoTrueOptions options;
  options.synthesis.seed = static_cast<std::uint32_t>(model.params().seed);
  return options;
}

std::unique_ptr<PhotoTrueAppearance> makePhotoTrueAppearance(const WoodModel& model,
                                                             const PhotoTrueSource& source,
                                                             const Progress& progress) {
  return std::make_unique<PhotoTrueAppearance>(model,
                                               loadAppearancePhotos(source.facePhotos, source.heldOutFaces),
                                               source.heldOutFaces, photoTrueOptionsFor(model), progress);
}

}  // namespace kerf
