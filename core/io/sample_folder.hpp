#pragma once
// Checks of a Mokume-style sample folder (A_col.png .. F_col.png, optional <F>_ann.png numbered rings
// and <F>_knot.png knot marks, optional block.json), with messages that name the file at fault.
// Used by projectFromSampleFolder (core/io/project.hpp).
#include <array>
#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>

#include "geometry/block.hpp"
#include "io/mokume_annotation_files.hpp"
#include "rings/annotations.hpp"

namespace kerf {

// `block.json` in the folder, {"size_mm": [x, y, z]}: the block of a sample that is not Mokume's
// 40 mm cube. nullopt when absent; InputError when malformed.
std::optional<glm::vec3> readSampleBlockSize(const std::filesystem::path& folder);

// The face photos A_col.png .. F_col.png (also .jpg, .jpeg, .tif, .tiff) of a sample folder, A..F as
// absolute paths; empty where a face has none.
std::array<std::filesystem::path, 6> findSampleFacePhotos(const std::filesystem::path& folder);

// The face photos (empty paths are missing faces) must be readable and agree with each other and the
// block: faces that share a block axis have the same number of pixels along it (opposite faces are the
// same size and edges that touch in the unfolded cross meet pixel for pixel), each photo has the
// proportions of its face (square for a cube, within 2 % or 1 px), and an annotation image covers its
// face (the photo's size or proportions, or Mokume's fixed 256 x 256, stretched over the face). Throws
// InputError naming the file. `blockFromFile` adds a hint to messages about a cube (the folder has no
// block.json).
void validateSampleFolder(const std::array<std::filesystem::path, 6>& photos,
                          const MokumeAnnotationFiles& annotations, const Block& block, bool blockFromFile);

}  // namespace kerf
