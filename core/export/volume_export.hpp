#pragma once
// Volumes of the wood model written as NRRD (io/nrrd_writer.hpp) or OpenVDB (export/vdb_writer.hpp), by
// the path's extension, computed one z slice at a time. A NRRD is streamed to disk, so a 512^3 volume
// needs memory for one slice; a VDB grid is held in memory until it is written (docs/export.md).
#include <filesystem>
#include <string>
#include <string_view>

#include "appearance/photo_true_appearance.hpp"
#include "field/ring_uncertainty.hpp"
#include "render/wood_model.hpp"
#include "util/progress.hpp"

namespace kerf {

enum class VolumeQuantity {
  Growth,           // float32: growth time in years (WoodSample::year); header key ring_levels lists the ring
                    // iso-values
  Color,            // uint8 RGB
  RingUncertainty,  // float32: how sure the fit is, the 1-sigma ring position in mm
                    // (field/ring_uncertainty.hpp)
};
// "growth" | "color" | "ring-uncertainty"; InputError otherwise
VolumeQuantity volumeQuantityFromName(std::string_view name);

struct VolumeExportResult {
  glm::ivec3 size{0};
  glm::vec3 spacingMm{0};
  std::size_t samples = 0;
  std::size_t bytes = 0;  // size of the file written
};

// `resolution` samples along the block's longest side (1..4096); the other sides get the same spacing,
// rounded to whole samples. Samples sit at voxel centres covering the block exactly.
// RingUncertainty needs `uncertainty` (InputError without it: "the project has no ring uncertainty ...").
// A Color volume with `photoTrue` is the photo-true appearance's (PhotoTrueAppearance::renderVolume, issue
// 17; header key appearance:=photo-true), otherwise the procedural model's.
VolumeExportResult exportVolume(const WoodModel& model, VolumeQuantity quantity, int resolution,
                                const std::filesystem::path& path, const Progress& progress = {},
                                const RingUncertainty* uncertainty = nullptr,
                                const PhotoTrueAppearance* photoTrue = nullptr);

}  // namespace kerf
