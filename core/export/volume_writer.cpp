#include "export/volume_writer.hpp"

#include <string>

#include "export/export_formats.hpp"
#include "export/vdb_writer.hpp"

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
  if (requireExportFormat(path, ExportKind::Volume, "a volume").format == ExportFormat::Vdb)
    return std::make_unique<VdbWriter>(path, layout);
  return std::make_unique<NrrdVolumeWriter>(path, layout);
}

}  // namespace kerf
