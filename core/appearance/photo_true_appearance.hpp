#pragma once
// The photo-true appearance (issue 17): any surface of the block made of the block's own photos, re-grown
// along the fitted growth field. The guidance features (appearance/guidance_features.hpp) are computed on
// the photographed faces and on the surface to show; guided patch synthesis (appearance/guided_synthesis.hpp)
// then fills the surface with photo patches whose features match, turned to its grain.
//
// Resolution: a surface is synthesised at the photos' own resolution (their pixels per mm; the photos hold
// no finer detail) and resampled to the resolution asked for.
//
// Surfaces that meet (two faces at an edge, a cut and the faces it crosses): each surface is synthesised
// on its own; they agree through the guidance. Ring phase, ring density, the sawing angles and the grain
// direction are functions of the 3D point, so the latewood bands, the heart/sap boundary and the grain
// run on across an edge as the field says; the finest detail (single pores, rays) does not continue
// across it. Why not a solid texture (Kopf et al. 2007): a volume at the photos' resolution (256^3 for a
// 40 mm cube) optimised against three orthogonal exemplar views costs minutes and hundreds of MB on two
// cores, and the photos of a block show each grain orientation only on the faces that have it, which a
// solid synthesis has to reconcile everywhere; constraining each surface at the edges it shares with
// others makes every surface depend on the order they were made in, and a cut depend on faces the user
// may never look at. Ring-level agreement is what a woodworker checks at an edge; see docs/texture.md.
//
// Held-out faces (Project::heldOutFaces, leave-one-face-out): their photos are never exemplars, even
// when they are passed in.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "appearance/guidance_features.hpp"
#include "appearance/guided_synthesis.hpp"
#include "appearance/photo_true_volume.hpp"
#include "appearance/surface_grid.hpp"
#include "geometry/cut_plane.hpp"
#include "geometry/face_set.hpp"
#include "io/image.hpp"
#include "util/progress.hpp"

namespace kerf {

class WoodModel;
struct Project;

struct PhotoTrueOptions {
  GuidanceWeights weights;
  GuidedSynthesisOptions synthesis;  // synthesis.seed is mixed with each surface's own
};

class PhotoTrueAppearance {
 public:
  // photos: A..F, empty where a face has none; passed by value, so that a caller that no longer needs them
  // moves them in and the exemplars take their pixels without a copy (at 1024 px a face, 75 MB). InputError
  // when no photo is left after the held-out faces, or a photo's proportions differ from its face's. The
  // model must outlive this object.
  PhotoTrueAppearance(const WoodModel& model, std::array<Image, 6> photos, const FaceSet& heldOut,
                      const PhotoTrueOptions& options = {}, const Progress& progress = {});

  float synthesisPxPerMm() const { return pxPerMm_; }
  const std::vector<FaceId>& exemplarFaces() const { return faces_; }

  // As renderFace / renderFaces / renderCut (render/renderers.hpp): RGB faces, an RGBA cut that is
  // transparent outside the block, the same image sizes and orientations.
  Image renderFace(FaceId face, glm::ivec2 size, const Progress& progress = {}) const;
  std::array<Image, 6> renderFaces(float pxPerMm, const Progress& progress = {}) const;
  Image renderCut(const CutPlane& plane, float pxPerMm, const Progress& progress = {}) const;
  // Any flat surface given as a grid at any resolution (a face pushed into the block for a depth stack):
  // synthesised at the photos' resolution over the grid's rectangle and resampled to the grid's pixels,
  // RGB. `salt` is mixed into the seed: one per surface, so that each has its own patches.
  Image renderGrid(const SurfaceGrid& grid, std::uint32_t salt, const Progress& progress = {}) const;
  // Any surface whose guidance is already computed at synthesisPxPerMm() (a part's texture atlas,
  // appearance/texel_guidance.hpp), RGB at the guidance's size.
  Image renderGuidance(const SurfaceGuidance& guidance, std::uint32_t salt,
                       const Progress& progress = {}) const;
  // The colour volume (appearance/photo_true_volume.hpp) for an export of `samples` voxels over the block:
  // synthesised at the photos' resolution across the slices and at most that along them, to be sampled
  // at the export's voxels. InputError when it would not fit in memory. Cancellable. Defined in
  // photo_true_volume.cpp.
  PhotoTrueVolume renderVolume(glm::ivec3 samples, const Progress& progress = {}) const;
  const PhotoTrueOptions& options() const { return options_; }

 private:
  const WoodModel& model_;
  PhotoTrueOptions options_;
  float pxPerMm_ = 0;
  std::vector<FaceId> faces_;
  // The photos and their guidance, packed once for every surface (appearance/exemplar_pyramids.hpp).
  std::shared_ptr<const PreparedExemplars> exemplars_;
};

// The project's face photos (Project::facePhotos) without its held-out faces. InputError naming the file
// when a photo is missing or unreadable, or when the project has no photo to take the appearance from.
std::array<Image, 6> loadAppearancePhotos(const Project& project);
// The same from the photos' files (A..F, empty where a face has none) and the held-out faces.
std::array<Image, 6> loadAppearancePhotos(const std::array<std::filesystem::path, 6>& facePhotos,
                                          const FaceSet& heldOut);

}  // namespace kerf
