#include "demo/demo_block.hpp"

#include "io/mokume_annotation_files.hpp"
#include "rings/annotations.hpp"
#include "rings/ring_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <random>

#include "io/atomic_file.hpp"
#include "io/block_knots_json.hpp"
#include "model/noise.hpp"
#include "render/renderers.hpp"
#include "util/error.hpp"

namespace kerf {
namespace fs = std::filesystem;

Project demoProject(std::uint32_t seed) {
  Project project;
  project.block = Block(glm::vec3(40.0f));
  project.params.seed = static_cast<float>(seed);
  // The schema defaults describe a ring-porous hardwood (chestnut-like) with the pith outside the
  // block behind face F; the demo uses them as they are, so "defaults" and "demo" agree. The growth
  // rates stay synthesised from the parameters (so the editor's growth sliders act on the demo);
  // truth.json records them explicitly.
  // Open with a slanted cut shown, so the first view already looks inside the block.
  project.cutPlane = CutPlaneSetting{4.0f, 35.0f, 20.0f};
  project.cutEnabled = true;
  return project;
}

void addDemoKnot(Project& project) {
  const WoodParameters& p = project.params;
  const PithAxis pith = PithAxis::fromAngles(p.pithOrigin, p.pithTilt, p.pithAzimuth);
  const glm::vec3 target(2, -4, 3);
  const glm::vec3 onPith = pith.origin + glm::dot(target - pith.origin, pith.direction) * pith.direction;
  BlockKnot knot;
  knot.id = 0;
  knot.origin = onPith;
  knot.direction = glm::normalize(target - onPith + 0.25f * glm::length(target - onPith) * pith.direction);
  knot.speed = 0.08f;
  project.knots = {knot};
  // A crisper union than the schema's default (Mokume starts its fits at s = 2): the rings bend within a
  // few knot radii instead of across the whole block.
  project.params.knotSmoothStem = 4.0f;
  // Entry and exit of the axis through the box (slabs), and the face each lies on.
  const glm::vec3 half = 0.5f * project.block.size();
  float tIn = -1e30f, tOut = 1e30f;
  int axisIn = 0, axisOut = 0;
  for (int a = 0; a < 3; ++a) {
    const float t0 = (-half[a] - knot.origin[a]) / knot.direction[a],
                t1 = (half[a] - knot.origin[a]) / knot.direction[a];
    if (std::min(t0, t1) > tIn) tIn = std::min(t0, t1), axisIn = a;
    if (std::max(t0, t1) < tOut) tOut = std::max(t0, t1), axisOut = a;
  }
  const auto faceOf = [&](glm::vec3 q, int a) {
    static constexpr FaceId kPlus[3] = {FaceId::E, FaceId::B, FaceId::A},
                            kMinus[3] = {FaceId::C, FaceId::D, FaceId::F};
    return q[a] > 0 ? kPlus[a] : kMinus[a];
  };
  for (const auto& [t, a] : {std::pair{tIn, axisIn}, std::pair{tOut, axisOut}}) {
    const glm::vec3 q = knot.origin + t * knot.direction;
    const FaceId face = faceOf(q, a);
    project.annotations.knots.push_back({0, face, blockToFaceMm(project.block, face, q)});
  }
}

void applyPhotoLook(Image& image, FaceId face, std::uint32_t seed) {
  const std::uint32_t h = noise::hash(faceIndex(face), static_cast<std::int32_t>(seed), 0xfaceu);
  const float lightAngle = noise::unit(noise::mix(h ^ 1u)) * 6.2831853f;
  const glm::vec2 lightDir(std::cos(lightAngle), std::sin(lightAngle));
  const glm::vec3 whiteBalance(1.0f + 0.04f * noise::signedUnit(noise::mix(h ^ 2u)),
                               1.0f + 0.02f * noise::signedUnit(noise::mix(h ^ 3u)),
                               1.0f + 0.04f * noise::signedUnit(noise::mix(h ^ 4u)));
  const float exposure = 1.0f + 0.05f * noise::signedUnit(noise::mix(h ^ 5u));
  std::mt19937 random(h);
  std::normal_distribution<float> sensor(0.0f, 0.012f);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const glm::vec2 q((x + 0.5f) / image.width - 0.5f, (y + 0.5f) / image.height - 0.5f);
      const float light = exposure * (1.0f + 0.12f * glm::dot(q, lightDir)) * (1.0f - 0.16f * glm::dot(q, q));
      float* px = image.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        px[c] = std::clamp(px[c] * light * whiteBalance[c] + sensor(random), 0.0f, 1.0f);
    }
  }
}

DemoFiles writeDemo(const fs::path& folder, const DemoOptions& options, const Progress& progress) {
  if (options.facePixels < 8 || options.facePixels > 8192)
    throw InputError("demo face size must be 8..8192 pixels");
  std::error_code error;
  fs::create_directories(folder, error);
  if (!fs::is_directory(folder)) throw InputError("cannot create folder " + folder.string());

  Project project = demoProject(options.seed);
  if (options.knot) addDemoKnot(project);
  const WoodModel model(project);
  DemoFiles files;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    Progress part{progress.report ? [&, i](double f) { progress.report((i + f) / 6.0); }
                                  : std::function<void(double)>{},
                  progress.stop};
    const glm::ivec2 size =
        model.block().faceImageSize(face, options.facePixels / model.block().face(face).widthMm);
    Image image = renderFace(model, face, size, options.samples, part);
    if (options.photoLook) applyPhotoLook(image, face, options.seed);
    files.photos[i] = folder / (std::string(1, faceLetter(face)) + "_col.png");
    writeImage(files.photos[i], image);
    project.facePhotos[i] = fs::absolute(files.photos[i]);
  }
  if (options.numberedTraces) {
    // Every true ring boundary pixel (rings/ring_metrics.hpp) carries the whole year it marks.
    for (FaceId face : kAllFaces) {
      const glm::ivec2 size = mokumeImageSize(model.block(), face);
      const Image rings = trueRingPixels(model, face, size);
      GrayImage8 numbered;
      numbered.width = size.x, numbered.height = size.y;
      numbered.pixels.assign(static_cast<std::size_t>(size.x) * size.y, 255);
      for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
          if (rings.pixel(x, y)[0] < 0.5f) continue;
          const float year =
              model.material().year(model.block().pixelCenter(face, x, y, size)) - project.params.ringOffset;
          numbered.pixels[static_cast<std::size_t>(y) * size.x + x] =
              static_cast<unsigned char>(std::clamp(static_cast<int>(std::lround(year)), 0, 254));
        }
      writeGrayImage8(folder / (std::string(1, faceLetter(face)) + kMokumeRingSuffix + ".png"), numbered);
    }
  }
  for (FaceId face : kAllFaces) {
    bool marked = false;
    for (const KnotMark& m : project.annotations.knots) marked = marked || m.face == face;
    if (!marked) continue;
    const GrayImage8 marks =
        knotImageFromMarks(project.annotations, face, project.block, mokumeImageSize(project.block, face));
    writeGrayImage8(folder / (std::string(1, faceLetter(face)) + kMokumeKnotSuffix + ".png"), marks);
  }
  files.truth = folder / "truth.json";
  nlohmann::json truth = {{"format", "kerf-demo-truth"},
                          {"version", 1},
                          {"description", "The true parameters the demo photos were rendered from."},
                          {"block", {{"size_mm", {40, 40, 40}}}},
                          {"face_pixels", options.facePixels},
                          {"samples_per_pixel_side", options.samples},
                          {"photo_look", options.photoLook},
                          {"parameters", parametersToJson(project.params)},
                          {"growth_rates", growthRatesToJson(project.effectiveRates())}};
  if (!project.knots.empty()) truth["knots"] = blockKnotsToJson(project.knots);
  writeTextAtomically(files.truth, truth.dump(2) + "\n");
  files.project = folder / "demo.kerf";
  saveProject(project, files.project);
  return files;
}

}  // namespace kerf
