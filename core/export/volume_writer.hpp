#pragma once
// Where exportVolume puts its slices: one interface over the volume formats, picked by the file's
// extension. NRRD (io/nrrd_writer.hpp) streams each slice to disk; OpenVDB (export/vdb_writer.hpp) keeps
// its sparse tree in memory until finish(), because a VDB file stores the whole tree's topology before
// any voxel (docs/export.md).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

#include "io/nrrd_writer.hpp"

namespace kerf {

class VolumeWriter {
 public:
  virtual ~VolumeWriter() = default;
  // The next z slice: size.x * size.y * components samples, x fastest (float or uint8 as the layout says).
  virtual void writeSlice(std::span<const float> slice) = 0;
  virtual void writeSlice(std::span<const std::uint8_t> slice) = 0;
  // Checks every slice was written and puts the file in place atomically. Throws InputError.
  virtual void finish() = 0;
};

// .nrrd or .vdb (any case); InputError for any other extension. The layout's fields mean the same for both.
std::unique_ptr<VolumeWriter> openVolumeWriter(const std::filesystem::path& path, const NrrdLayout& layout);

}  // namespace kerf
