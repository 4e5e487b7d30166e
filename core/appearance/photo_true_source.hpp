#pragma once
// What a long job (an export, on the editor's background thread or in kerf-cli) needs to make a project's
// photo-true appearance: the face photos' files and the held-out faces, copied from the project when the
// job is set up and read only when it runs (reading and analysing the photos takes seconds).
#include <array>
#include <filesystem>
#include <memory>
#include <optional>

#include "appearance/photo_true_appearance.hpp"
#include "geometry/face_set.hpp"
#include "util/progress.hpp"

namespace kerf {

class WoodModel;
struct Project;

struct PhotoTrueSource {
  std::array<std::filesystem::path, 6> facePhotos;
  FaceSet heldOutFaces;
};

// The project's source when it stores the photo-true appearance (Project::appearance); none when procedural.
std::optional<PhotoTrueSource> photoTrueSourceOf(const Project& project);

// The options every command uses: the synthesis seed is the model's (model.seed), so that the same project
// gives the same surfaces in render-faces, render-cut and export.
PhotoTrueOptions photoTrueOptionsFor(const WoodModel& model);

// Reads the photos (InputError naming a missing or unreadable file) and analyses them. The model must
// outlive the result.
std::unique_ptr<PhotoTrueAppearance> makePhotoTrueAppearance(const WoodModel& model,
                                                             const PhotoTrueSource& source,
                                                             const Progress& progress = {});

}  // namespace kerf
