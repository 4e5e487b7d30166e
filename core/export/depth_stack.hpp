#pragma once
// A depth stack for milling: the surface of a face after removing 0, step, 2 step, .. up to depth mm of
// wood, as numbered PNG images in a folder (FACE_000.png, FACE_001.png, ..) with an index of the depths
// (depths.csv and depths.json). Each image covers the face's rectangle at the same pixel grid as the face
// image, pushed `depth` mm into the block along the face's inward normal. The colour is the wood's own,
// without the per-face photo tint the face images carry (a tint models the photograph, not the wood).
#include <filesystem>
#include <string>
#include <vector>

#include "export/image_export.hpp"

namespace kerf {

struct DepthStackOptions {
  FaceId face = FaceId::A;
  float stepMm = 1.0f;
  float depthMm = 5.0f;  // the last surface is at the largest multiple of step not beyond depth
  float pxPerMm = 10.0f;
  int samples = 2;
  ImageLayer layer = ImageLayer::Colour;  // what each PNG holds
};

// "A,1,5" -> face A, step 1 mm, depth 5 mm. Throws InputError with the expected syntax.
DepthStackOptions parseDepthStack(const std::string& text);

// The surface at `depthMm` below the face (layers as renderFaceLayers, no tint). Throws InputError when
// the depth is negative or reaches through the block. With `photoTrue` the colour is the photo-true
// appearance's: at depth 0 the face's own (renderFace), deeper each surface synthesised on its own (the
// rings, grain and heart/sap follow the field from image to image; single pores do not continue).
LayeredImage renderFaceAtDepth(const WoodModel& model, FaceId face, float depthMm, float pxPerMm, int samples,
                               const Progress& progress = {}, const PhotoTrueAppearance* photoTrue = nullptr);

struct DepthStackResult {
  std::vector<float> depthsMm;
  std::vector<std::filesystem::path> files;
  std::filesystem::path index;  // depths.csv
};

// Creates the folder if needed; each file is written atomically, the index last.
DepthStackResult exportDepthStack(const WoodModel& model, const DepthStackOptions& options,
                                  const std::filesystem::path& folder, const Progress& progress = {},
                                  const PhotoTrueAppearance* photoTrue = nullptr);

}  // namespace kerf
