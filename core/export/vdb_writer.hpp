#pragma once
// OpenVDB volumes (.vdb, read by Blender, Houdini and ParaView): one grid named after the quantity,
// "growth" (float, years) or "color" (vec3s in 0..1, stored as half in the file), with a transform that
// puts voxel centres at the block's millimetre coordinates (layout.origin + index * layout.spacing) and the
// layout's key values as grid metadata. OpenVDB writes a grid as a whole, so the slices are gathered into
// the grid's tree (every voxel active) and the file is written, atomically, by finish().
#include <memory>

#include "export/volume_writer.hpp"

namespace kerf {

class VdbWriter : public VolumeWriter {
 public:
  // Checks the folder exists (InputError); nothing is written before finish().
  VdbWriter(const std::filesystem::path& path, const NrrdLayout& layout);
  ~VdbWriter() override;

  void writeSlice(std::span<const float> slice) override;
  void writeSlice(std::span<const std::uint8_t> slice) override;
  void finish() override;

 private:
  struct Grid;
  std::filesystem::path path_;
  NrrdLayout layout_;
  std::unique_ptr<Grid> grid_;
  int slicesWritten_ = 0;
};

}  // namespace kerf
