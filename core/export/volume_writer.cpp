#include "export/volume_writer.hpp"

#include <string>

#include "export/vdb_writer.hpp"
#include "util/error.hpp"
#include "util/file_extension.hpp"

namespace kerf {
namespace {

class NrrdVolumeWriter : public VolumeWriter {
 public:
  NrrdVolumeWriter(const std::filesystem::path& path, const NrrdLayout& layout) : writer_(path, layout) {}
  void writeSlice(std::span<const float> slice) override { writer_.writeSlice(slice); }
  void writeSlice(std::span<const std::uint8_t> slice) override { writer_.writeSlice(slice); }
  void finish() override { writer_.finish(); }

 private:
  NrrdWriter writer_;
};

}  // namespace

std::unique_ptr<VolumeWriter> openVolumeWriter(const std::filesystem::path& path, const NrrdLayout& layout) {
  const std::string extension = lowerExtension(path);
  if (extension == ".nrrd") return std::make_unique<NrrdVolumeWriter>(path, layout);
  if (extension == ".vdb") return std::make_unique<VdbWriter>(path, layout);
  throw InputError("cannot write a volume as \"" + extension + "\" (use .nrrd or .vdb)");
}

}  // namespace kerf
