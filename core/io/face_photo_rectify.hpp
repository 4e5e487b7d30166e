#pragma once
// Turning the user's own photo of one block face into a face image: pick the face's four corners on the
// photo, rectify the perspective, turn/mirror it into the face's image orientation, white-balance it.
//
// Corner order. `corners` are the face's corners on the photo, in the photo's continuous pixel
// coordinates (docs/coordinates.md: the centre of pixel (c, r) is at (c + 0.5, r + 0.5); (0, 0) is the
// photo's top-left corner), going **clockwise as seen on the photo**:
//   corners[0] -> top-left, [1] -> top-right, [2] -> bottom-right, [3] -> bottom-left
// of the *rectified* picture, before rotation and flip. Rotation (quarter turns clockwise) and then flip
// (mirror left <-> right) take that picture into the face's own image orientation of the table in
// docs/coordinates.md (core/geometry/block.hpp: image right and down on each face). So with rotation 0
// and no flip, corners[0] is the face image's top-left corner (continuous (0, 0)), corners[1] its
// top-right (width, 0), corners[2] (width, height), corners[3] (0, height).
//
// Face sizes. The face image is the face's size in mm times a chosen px/mm (Block::faceImageSize), so a
// cuboid's long faces get long images; the warp goes straight to the pre-rotation size (height and width
// swapped for a quarter turn) and the quarter turn itself moves pixels exactly.
#include <array>
#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <string>

#include "geometry/block.hpp"
#include "io/image.hpp"

namespace kerf {

struct FacePhotoSetup {
  std::filesystem::path source;        // the photo
  std::array<glm::vec2, 4> corners{};  // photo continuous pixels, clockwise (see above)
  int rotationDegrees = 0;             // 0, 90, 180 or 270, clockwise, applied after rectifying
  bool flip = false;                   // mirror left <-> right, applied after the rotation
  glm::vec3 whiteBalance{1.0f};        // per-channel gains applied to the rectified image

  bool operator==(const FacePhotoSetup&) const = default;
};

// Throws InputError unless the four corners are finite, lie on (or within a pixel of) a photo of
// `photoSize` pixels, and form a convex quadrilateral going clockwise on the photo whose sides are at
// least 4 px long and whose area is at least 64 px^2. Messages name the corner (1..4) or the problem.
void validateCorners(const std::array<glm::vec2, 4>& corners, glm::ivec2 photoSize);

// 0, 90, 180, 270 (any multiple of 90 is normalised); anything else is an InputError.
int normalizedRotation(int degrees);

// The image turned `rotationDegrees` clockwise, then mirrored left <-> right if `flip`. Exact (pixels
// are moved, not resampled).
Image orientImage(const Image& image, int rotationDegrees, bool flip);
// Where a point of a w x h picture (continuous coordinates) lands after orientImage.
glm::vec2 orientPoint(glm::vec2 p, glm::ivec2 size, int rotationDegrees, bool flip);
// Which side of the oriented picture side `side` (0 top, 1 right, 2 bottom, 3 left) of the rectified
// picture becomes.
int orientedSide(int side, int rotationDegrees, bool flip);
// The faces that share each edge of `face`'s image (0 top, 1 right, 2 bottom, 3 left), e.g. A: B, E,
// D, C (docs/coordinates.md).
std::array<FaceId, 4> faceEdgeNeighbours(FaceId face);

// Rectifies the quadrilateral `setup.corners` of `photo` onto a picture that becomes exactly `faceSize`
// pixels after setup's rotation and flip, then applies setup.whiteBalance. Perspective warp with
// bicubic interpolation (values clamped to 0..1); where the photo has several pixels per output pixel
// it is first area-averaged down (cv::INTER_AREA) to about 1.5 photo pixels per output pixel along
// the face's least-shrunk side, so fine grain does not alias. The photo's channel count is kept.
// Throws InputError (bad corners, bad size, bad rotation).
Image rectifyFace(const Image& photo, const FacePhotoSetup& setup, glm::ivec2 faceSize);
// The same, reading setup.source (InputError names the file).
Image rectifyFacePhoto(const FacePhotoSetup& setup, glm::ivec2 faceSize);

// Photo pixels per millimetre along the quadrilateral's sides for a face of faceMm (width, height in the
// face image orientation): {smallest, largest} over the four sides. A rectified face at more px/mm
// than the smallest invents detail.
glm::vec2 photoResolution(const std::array<glm::vec2, 4>& corners, glm::vec2 faceMm, int rotationDegrees);

// White balance. Gains g make a reference colour neutral while keeping its luminance (Rec. 709 weights):
// g_c = Y(ref) / ref_c. Gains are limited to 0.25 .. 4.
//
// From a neutral patch (a grey card, white paper, unfinished maple) picked on the photo: the patch's mean
// colour is the reference; `rect` is x, y, width, height in photo continuous pixels. Throws InputError
// when the patch is outside the photo, smaller than a pixel, or too dark or clipped to say anything.
glm::vec3 whiteBalanceFromPatch(const Image& photo, glm::vec4 rect);
// Automatic: a robust white-patch estimate. Wood is never grey, so grey-world (the mean colour is
// neutral) would bleach every face towards grey. Instead the reference is the mean of the brightest
// unclipped pixels of the whole photo (luminance between the 97th and 99.5th percentile, pixels with a
// channel >= 0.98 left out): in a photo of a block those are the paper, bench or card it stands on and
// the sheen of the surface, which under the dichromatic reflection model have the light's colour.
// Pixels are sampled on a grid (at most ~250k). Returns gains 1 for an empty or black photo. Picking a
// neutral patch is the reliable way; this is the quick one.
glm::vec3 autoWhiteBalance(const Image& photo);
void applyWhiteBalance(Image& image, glm::vec3 gains);

// The photo area-averaged down so its longer side is at most maxSide (unchanged when it already is);
// continuous coordinates scale by exactly (result.width / photo.width, result.height / photo.height).
Image downscaleImage(const Image& photo, int maxSide);

// The face a photo's file name names: "A_col.png", "b-top.jpg", "C.tif", "D face.png" -> that face;
// anything else (no letter A..F followed by '_', '-', '.', or ' ') -> nullopt.
std::optional<FaceId> faceFromFileName(const std::string& fileName);

}  // namespace kerf
