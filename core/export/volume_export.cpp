#include "export/volume_export.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "export/export_formats.hpp"
#include "export/volume_writer.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {

VolumeQuantity volumeQuantityFromName(std::string_view name) {
  if (name == "growth") return VolumeQuantity::Growth;
  if (name == "color" || name == "colour") return VolumeQuantity::Color;
  if (name == "ring-uncertainty") return VolumeQuantity::RingUncertainty;
  throw InputError("unknown volume quantity \"" + std::string(name) +
                   "\" (use growth, color or ring-uncertainty)");
}

namespace {

// A volume is written slice by slice (NRRD, raw) or kept whole until written (OpenVDB): refuse at once
// what the disk or the memory cannot hold, instead of failing an hour into a 4096^3 export.
void checkVolumeFits(const std::filesystem::path& path, glm::ivec3 n, int bytesPerSample) {
  const std::uint64_t samples = std::uint64_t(n.x) * std::uint64_t(n.y) * std::uint64_t(n.z);
  const std::string size = std::to_string(n.x) + " x " + std::to_string(n.y) + " x " + std::to_string(n.z);
  const std::optional<ExportFormatInfo> format = exportFormatOf(path);
  if (format && format->format == ExportFormat::Vdb) {
    // OpenVDB's dense leaves: a float (growth) or 3 floats (colour) per voxel, plus about 6 % for the tree.
    const std::uint64_t perSample = bytesPerSample == 4 ? 4 : 12;
    checkMemoryNeed(samples * perSample / 16 * 17, "the " + size + " VDB volume");
    return;
  }
  std::error_code ec;
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  const std::filesystem::space_info space = std::filesystem::space(folder, ec);
  const std::uint64_t bytes = samples * std::uint64_t(bytesPerSample);
  if (!ec && bytes > space.available) {
    std::ostringstream s;
    s.precision(3);
    s << "the " << size << " volume needs " << bytes / double(1ull << 30) << " GiB on disk; "
      << folder.string() << " has " << space.available / double(1ull << 30)
      << " GiB free: lower the resolution";
    throw InputError(s.str());
  }
}

}  // namespace

VolumeExportResult exportVolume(const WoodModel& model, VolumeQuantity quantity, int resolution,
                                const std::filesystem::path& path, const Progress& wholeProgress,
                                const RingUncertainty* uncertainty, const PhotoTrueAppearance* photoTrue) {
  const bool sure = quantity == VolumeQuantity::RingUncertainty;
  if (sure && (!uncertainty || uncertainty->empty()))
    throw InputError(
        "the project has no ring uncertainty of its current field: fit it with `kerf-cli fit --uncertainty "
        "8` "
        "(or let the editor's fit estimate it) first");
  if (resolution < 1 || resolution > 4096) throw InputError("volume resolution must be 1..4096 samples");
  const glm::vec3 size = model.block().size();
  const float longest = std::max({size.x, size.y, size.z});
  glm::ivec3 n;
  for (int a = 0; a < 3; ++a)
    n[a] = std::max(1, static_cast<int>(std::lround(resolution * size[a] / longest)));
  const glm::vec3 spacing = size / glm::vec3(n);
  const glm::vec3 origin = -0.5f * size + 0.5f * spacing;

  NrrdLayout layout;
  layout.size = n;
  layout.spacing = spacing;
  layout.origin = origin;
  layout.keyValues.emplace_back("generator", "Kerf");
  const bool growth = quantity == VolumeQuantity::Growth;
  if (sure) {
    layout.type = NrrdLayout::Type::Float32;
    layout.comment = "Kerf fit uncertainty: 1-sigma ring position in mm at each sample (block frame, mm)";
    layout.keyValues.emplace_back("quantity", "ring_uncertainty");
    layout.keyValues.emplace_back("units", "mm");
    layout.keyValues.emplace_back("refits", std::to_string(uncertainty->replicates));
  } else if (growth) {
    layout.type = NrrdLayout::Type::Float32;
    layout.comment = "Kerf growth field: years since the pith at each sample (block frame, mm)";
    layout.keyValues.emplace_back("quantity", "growth");
    layout.keyValues.emplace_back("units", "years");
    // Ring levels over the field's range in the block: a coarse pass, widened by one ring each way.
    float lo = std::numeric_limits<float>::max(), hi = -lo;
    constexpr int m = 16;
    for (int i = 0; i <= m; ++i)
      for (int j = 0; j <= m; ++j)
        for (int k = 0; k <= m; ++k) {
          const float g = model.material().year(-0.5f * size + size * glm::vec3(i, j, k) / float(m));
          lo = std::min(lo, g), hi = std::max(hi, g);
        }
    std::ostringstream levels;
    levels.precision(7);
    for (float level : ringLevels(model.params().ringOffset, std::max(0.0f, lo - 1.0f), hi + 1.0f)) {
      levels << (levels.tellp() > 0 ? " " : "") << level;
    }
    layout.keyValues.emplace_back("ring_levels", levels.str());
  } else {
    layout.type = NrrdLayout::Type::UInt8;
    layout.components = 3;
    layout.comment = "Kerf wood colour (sRGB-encoded 8-bit) in the block frame";
    layout.keyValues.emplace_back("quantity", "color");
    layout.keyValues.emplace_back("appearance", photoTrue ? "photo-true" : "procedural");
  }

  const bool floatSamples = growth || sure;
  checkVolumeFits(path, n, floatSamples ? 4 : 3);
  const bool photoColour = photoTrue && quantity == VolumeQuantity::Color;
  // The photo-true volume is synthesised first, then sampled at the voxels (most of the time is its).
  PhotoTrueVolume photoVolume;
  if (photoColour) photoVolume = photoTrue->renderVolume(n, wholeProgress.part(0.0, 0.9));
  const Progress progress = photoColour ? wholeProgress.part(0.9, 1.0) : wholeProgress;
  const std::unique_ptr<VolumeWriter> writer = openVolumeWriter(path, layout);  // .nrrd or .vdb
  const std::size_t sliceSamples = static_cast<std::size_t>(n.x) * n.y;
  std::vector<float> floats(floatSamples ? sliceSamples : 0);
  std::vector<std::uint8_t> bytes(floatSamples ? 0 : sliceSamples * 3);
  for (int z = 0; z < n.z; ++z) {
    progress.throwIfCancelled();
    const float pz = origin.z + z * spacing.z;
    parallelRows(n.y,
                 [&](int y) {
                   const float py = origin.y + y * spacing.y;
                   for (int x = 0; x < n.x; ++x) {
                     const glm::vec3 p(origin.x + x * spacing.x, py, pz);
                     const std::size_t i = static_cast<std::size_t>(y) * n.x + x;
                     if (sure) {
                       floats[i] = uncertainty->at(model.block(), p);
                     } else if (growth) {
                       floats[i] = model.material().year(p);
                     } else {
                       const glm::vec3 c = photoColour ? photoVolume.colourAt(p) : model.evaluate(p).color;
                       for (int ch = 0; ch < 3; ++ch)
                         bytes[i * 3 + ch] = static_cast<std::uint8_t>(std::lround(c[ch] * 255.0f));
                     }
                   }
                 },
                 {nullptr, progress.stop});
    if (floatSamples)
      writer->writeSlice(std::span<const float>(floats));
    else
      writer->writeSlice(std::span<const std::uint8_t>(bytes));
    progress.set(static_cast<double>(z + 1) / n.z);
  }
  writer->finish();
  VolumeExportResult result;
  result.size = n;
  result.spacingMm = spacing;
  result.samples = sliceSamples * n.z;
  result.bytes = std::filesystem::file_size(path);  // VDB is compressed
  return result;
}

}  // namespace kerf
