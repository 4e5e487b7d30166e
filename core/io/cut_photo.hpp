#pragma once
// A photo of a real cut, laid on the model's cut to compare them (issue 16 item 5). A woodworker saws
// the board on the cut plane, photographs the sawn surface and aligns the photo to the cut: the photo's
// four corners (face_photo_rectify.hpp's corner order, clockwise on the photo) go to the corners of the
// rectangle bounding the cut, the picture renderCut and cutGrid cover (top-left at the plane's (min
// right, max up); docs/coordinates.md), after the rotation and mirror of FacePhotoSetup.
//
// The photo belongs to the plane it was aligned on: on another plane it shows nothing of the model's cut.
#include <array>
#include <filesystem>
#include <glm/vec2.hpp>
#include <nlohmann/json_fwd.hpp>

#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"
#include "image/image.hpp"
#include "io/face_photo_rectify.hpp"

namespace kerf {

struct CutPhoto {
  FacePhotoSetup setup;  // the photo's file (absolute in memory), its corners, turn and mirror
  CutPlaneSetting plane;

  bool operator==(const CutPhoto&) const = default;
};

// Whether `setting` is the plane the photo was aligned on (within a hundredth of a mm and of a degree:
// the same plane, whatever rounding a slider or a file gave it).
bool cutPhotoBelongsTo(const CutPhoto& photo, const CutPlaneSetting& setting);

// The corners of a whole photo of `size` pixels: the default alignment, the photo framed on the cut.
std::array<glm::vec2, 4> wholePhotoCorners(glm::ivec2 size);

// The px/mm of the aligned picture: the photo's own resolution along the cut (its least-resolved side),
// capped so the picture's longer side is at most maxSide pixels. InputError when the plane misses the block.
float cutPhotoPxPerMm(const CutPhoto& photo, glm::ivec2 photoSize, const Block& block, int maxSide);

// The photo rectified onto the cut's rectangle at pxPerMm: the size and grid of cutGrid(block, plane,
// pxPerMm), so pixel (x, y) lies where renderCut's pixel (x, y) does. InputError for bad corners or a
// plane that misses the block.
Image rectifyCutPhoto(const Image& photo, const CutPhoto& cut, const Block& block, float pxPerMm);

// JSON (the project's optional key "cut_photo"): the photo's path relative to `baseDir` where it can be,
// the corners, rotation, mirror and plane. InputError naming the field.
nlohmann::json cutPhotoToJson(const CutPhoto& photo, const std::filesystem::path& baseDir);
CutPhoto cutPhotoFromJson(const nlohmann::json& json, const std::filesystem::path& baseDir);

}  // namespace kerf
