#pragma once
// Where on each face the texture inference looks: a few small crops per photographed face, at seeded
// positions, rendered from the model at exactly the photo's pixel grid (so a crop of the rendering and
// the same crop of the photo cover the same wood). And what each face shows of the wood: end grain or
// side grain, which decides what its texture looks like (learned-inference paper Sec. 3.3).
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "field/pith_axis.hpp"
#include "geometry/block.hpp"
#include "io/image.hpp"
#include "material/wood_material.hpp"

namespace kerf {

class WoodModel;

struct FaceCrop {
  FaceId face = FaceId::A;
  int x = 0, y = 0, width = 0, height = 0;  // pixels of the face image (top-left corner, size)
};

struct FaceCropLayout {
  std::array<glm::ivec2, 6> imageSize{};  // each face image's size in pixels (that of its photo)
  std::array<float, 6> pxPerMm{};         // 0 where a face has no photo
  std::vector<FaceCrop> crops;            // face by face, A..F
};

// Checks every photo's proportions against its face (InputError naming the face when they differ by more
// than 2 %) and places `perFace` crops of up to `size` px on each photographed face, at positions drawn
// from `seed` (deterministic), away from the outermost pixels (photo edges are often damaged).
FaceCropLayout placeFaceCrops(const Block& block, const std::array<Image, 6>& photos, int perFace, int size,
                              std::uint32_t seed);

Image cropImage(const Image& image, const FaceCrop& crop);

// The crop rendered from the model on the face image grid of imageSize, `samples` x `samples` points per
// pixel (as renderFace). Single-threaded: the caller runs crops or candidates in parallel.
Image renderFaceCrop(const WoodModel& model, const FaceCrop& crop, glm::ivec2 imageSize, int samples);

// The same in two steps. locateFaceCrop: where each of the crop's points lies in the tree
// (WoodMaterial::locate), pixel by pixel, `samples` x `samples` each. renderFaceCrop from them: the same
// pixels as above for any model whose locations are these (the same field, distortion and knots; texture
// parameters may differ). The texture search locates once and shades every candidate: locating is half
// the cost of a point.
std::vector<WoodLocation> locateFaceCrop(const WoodModel& model, const FaceCrop& crop, glm::ivec2 imageSize,
                                         int samples);
Image renderFaceCrop(const WoodModel& model, const FaceCrop& crop, const std::vector<WoodLocation>& located,
                     int samples);

// What a face shows of the wood, from its normal relative to the pith axis at the face centre.
enum class FaceGrain { EndGrain, FlatSawn, QuarterSawn };
struct FaceOrientation {
  FaceGrain grain = FaceGrain::EndGrain;
  float angleToPithDeg = 0;  // between the face normal and the pith axis (0 = end grain)
};
FaceOrientation faceOrientation(const Block& block, FaceId face, const PithAxis& axis);
std::string faceGrainName(FaceGrain grain);  // "end grain", "side grain (flat-sawn)", ...

}  // namespace kerf
