#include "export/depth_stack.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "appearance/photo_true_appearance.hpp"
#include "appearance/surface_grid.hpp"
#include "io/atomic_file.hpp"
#include "util/error.hpp"
#include "util/number_list.hpp"
#include "util/parallel.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

// How far the block reaches behind a face (its thickness along the face's normal).
float thicknessBehind(const Block& block, FaceId face) {
  const glm::vec3 n = glm::abs(block.face(face).normal);
  return glm::dot(n, block.size());
}

// The photo-true colour of the face pushed `depthMm` into the block: its own seed for each face and depth.
Image photoTrueAtDepth(const PhotoTrueAppearance& appearance, const Block& block, FaceId face, float depthMm,
                       glm::ivec2 size, const Progress& progress) {
  if (depthMm == 0.0f) return appearance.renderFace(face, size, progress);
  SurfaceGrid grid = faceGrid(block, face, size);
  grid.origin -= block.face(face).normal * depthMm;
  std::uint32_t bits;
  std::memcpy(&bits, &depthMm, sizeof bits);
  return appearance.renderGrid(grid, bits ^ (0x51ED27u + 0x9E3779B1u * std::uint32_t(faceIndex(face))),
                               progress);
}

}  // namespace

DepthStackOptions parseDepthStack(const std::string& text) {
  const auto comma = text.find(',');
  const auto face = comma == 1 ? faceFromLetter(text[0]) : std::nullopt;
  if (!face) throw InputError("--depth-stack takes FACE,STEP_MM,DEPTH_MM, e.g. A,0.5,5 (face A..F)");
  const std::vector<float> numbers = parseNumberList(text.substr(2), "--depth-stack");
  if (numbers.size() != 2) throw InputError("--depth-stack takes FACE,STEP_MM,DEPTH_MM, e.g. A,0.5,5");
  DepthStackOptions options;
  options.face = *face;
  options.stepMm = numbers[0];
  options.depthMm = numbers[1];
  if (!(options.stepMm > 0.0f)) throw InputError("--depth-stack: the step must be more than 0 mm");
  if (!(options.depthMm >= 0.0f)) throw InputError("--depth-stack: the depth must be 0 mm or more");
  return options;
}

LayeredImage renderFaceAtDepth(const WoodModel& model, FaceId face, float depthMm, float pxPerMm, int samples,
                               const Progress& progress, const PhotoTrueAppearance* photoTrue) {
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("pixels per mm must be a positive number");
  if (samples < 1 || samples > 8) throw InputError("samples per pixel side must be 1..8");
  const Block& block = model.block();
  const float thickness = thicknessBehind(block, face);
  if (!(depthMm >= 0.0f) || depthMm >= thickness) {
    std::ostringstream s;
    s << "a depth of " << depthMm << " mm is outside the block (face " << faceLetter(face) << " has "
      << thickness << " mm of wood behind it)";
    throw InputError(s.str());
  }
  const glm::ivec2 size = block.faceImageSize(face, pxPerMm);
  checkImageSize(size, "the image of face " + std::string(1, faceLetter(face)), pxPerMm);
  const glm::vec3 inward = -block.face(face).normal * depthMm;
  LayeredImage out;
  out.pxPerMm = pxPerMm;
  out.colour = Image(size.x, size.y, 3);
  out.growth = Image(size.x, size.y, 1);
  out.rings = Image(size.x, size.y, 1);
  out.photoTrue = photoTrue != nullptr;
  if (photoTrue)
    out.colour = photoTrueAtDepth(*photoTrue, block, face, depthMm, size, progress.part(0.0, 0.9));
  const float weight = 1.0f / (samples * samples);
  parallelRows(
      size.y,
      [&](int y) {
        for (int x = 0; x < size.x; ++x) {
          out.growth.pixel(x, y)[0] = model.material().year(block.pixelCenter(face, x, y, size) + inward);
          if (photoTrue) continue;
          glm::vec3 sum(0.0f);
          for (int sy = 0; sy < samples; ++sy)
            for (int sx = 0; sx < samples; ++sx) {
              const glm::vec2 pos(x + (sx + 0.5f) / samples, y + (sy + 0.5f) / samples);
              sum += model.evaluate(block.imageToBlock(face, pos, size) + inward).color;
            }
          float* c = out.colour.pixel(x, y);
          c[0] = sum.x * weight, c[1] = sum.y * weight, c[2] = sum.z * weight;
        }
      },
      photoTrue ? progress.part(0.9, 1.0) : progress);
  addRingLines(model, out);
  return out;
}

DepthStackResult exportDepthStack(const WoodModel& model, const DepthStackOptions& options,
                                  const std::filesystem::path& folder, const Progress& progress,
                                  const PhotoTrueAppearance* photoTrue) {
  if (!(options.stepMm > 0.0f)) throw InputError("the depth step must be more than 0 mm");
  if (std::filesystem::exists(folder) && !std::filesystem::is_directory(folder))
    throw InputError("cannot write the depth stack into " + folder.string() + ": it is a file, not a folder");
  DepthStackResult result;
  // In double, checked before the conversion: 1 / 1e-30 does not fit an int (issue 21).
  const double images = std::floor(double(options.depthMm) / options.stepMm + 1e-4) + 1.0;
  if (!(images <= 10000.0)) {
    std::ostringstream s;
    s << "the depth stack would have more than 10000 images (" << options.depthMm << " mm in steps of "
      << options.stepMm << " mm); raise the step";
    throw InputError(s.str());
  }
  const int count = static_cast<int>(images);
  for (int i = 0; i < count; ++i) result.depthsMm.push_back(i * options.stepMm);
  // Check the deepest surface before writing anything.
  const float thickness = thicknessBehind(model.block(), options.face);
  if (result.depthsMm.back() >= thickness) {
    std::ostringstream s;
    s << "a depth of " << result.depthsMm.back() << " mm is outside the block (face "
      << faceLetter(options.face) << " has " << thickness << " mm of wood behind it)";
    throw InputError(s.str());
  }
  const bool folderExisted = std::filesystem::exists(folder);
  createOutputFolder(folder);

  ImageWriteOptions write;
  write.pngLayer = options.layer;
  std::ostringstream csv, json;
  csv << "index,file,depth_mm\n";
  json << "{\"face\":\"" << faceLetter(options.face) << "\",\"px_per_mm\":" << options.pxPerMm
       << ",\"layer\":\"" << imageLayerName(options.layer) << "\",\"images\":[";
  // A stack is written whole or not at all: a cancelled or failed export removes the images it wrote
  // (and the folder it made), so no stack without its index is left behind.
  try {
    for (int i = 0; i < count; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "%c_%03d.png", faceLetter(options.face), i);
      const LayeredImage image =
          renderFaceAtDepth(model, options.face, result.depthsMm[i], options.pxPerMm, options.samples,
                            progress.part(double(i) / count, double(i + 1) / count), photoTrue);
      writeLayeredImage(folder / name, image, write);
      result.files.push_back(folder / name);
      csv << i << "," << name << "," << result.depthsMm[i] << "\n";
      json << (i ? "," : "") << "{\"file\":\"" << name << "\",\"depth_mm\":" << result.depthsMm[i] << "}";
    }
    json << "]}\n";
    writeTextAtomically(folder / "depths.json", json.str());
    result.index = folder / "depths.csv";
    writeTextAtomically(result.index, csv.str());
  } catch (...) {
    std::error_code ignored;
    for (const std::filesystem::path& file : result.files) std::filesystem::remove(file, ignored);
    std::filesystem::remove(folder / "depths.json", ignored);
    if (!folderExisted) std::filesystem::remove(folder, ignored);  // only when empty
    throw;
  }
  return result;
}

}  // namespace kerf
