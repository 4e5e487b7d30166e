#pragma once
// Kerf's own demo data: a block rendered from known procedural parameters, with the look of real
// photographs (uneven light, white balance, vignetting, sensor noise). The output folder is a valid
// Mokume-style sample (A_col.png .. F_col.png) plus the true parameters and a project file, so every
// later tool (detection, fitting) can be checked against the truth.
#include <cstdint>
#include <filesystem>

#include "io/image.hpp"
#include "io/project.hpp"
#include "util/progress.hpp"

namespace kerf {

struct DemoOptions {
  int facePixels = 512;    // face image side (the Mokume dataset uses 256 for its 40 mm cubes)
  int samples = 3;         // supersampling per pixel side
  std::uint32_t seed = 7;  // model.seed of the demo wood
  bool photoLook = true;   // add lighting/colour/noise effects to the faces
  // Also write the true rings as numbered traces in the Mokume annotation format (<F>_ann.png at
  // Mokume's 6.4 px/mm, pixel value = the ring's year), as a user who traced every ring would.
  bool numberedTraces = false;
  // A knot from the pith through the block (Mokume Sec. 5.2.4), in the project, with its two centres
  // marked as knot marks (the project's annotations and Mokume's <F>_knot.png).
  bool knot = false;
};

// The demo block's true parameters: a 40 mm cube of ring-porous hardwood with its pith outside the block.
Project demoProject(std::uint32_t seed = 7);
// The demo's knot (DemoOptions::knot): a knot leaving the pith through the block, leaning up along the stem
// as branches do, and its centres marked where its axis enters and leaves the block (the marks a user would
// make).
void addDemoKnot(Project& project);

// Applies the photograph look to a rendered face, deterministically from (face, seed).
void applyPhotoLook(Image& image, FaceId face, std::uint32_t seed);

struct DemoFiles {
  std::filesystem::path project;  // demo.kerf
  std::filesystem::path truth;    // truth.json: the parameters and growth rates used
  std::array<std::filesystem::path, 6> photos;
};

// Writes the demo into `folder` (created if needed). Throws InputError, Cancelled.
DemoFiles writeDemo(const std::filesystem::path& folder, const DemoOptions& options = {},
                    const Progress& progress = {});

}  // namespace kerf
