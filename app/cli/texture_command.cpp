// texture: infer the detail of the wood texture (pores, rays, fibres, the early-to-late transition) of a
// project whose growth field is fitted, from its face photos (Mokume Sec. 5.3.1 / A.2.3; the pipeline is
// inferTexture, texture/texture_inference.hpp), and write the project with the inferred parameters.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <sstream>
#include "command.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "number_option.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "texture_step.hpp"
#include "util/error.hpp"

namespace kerf::cli {

namespace fs = std::filesystem;

namespace {

// The photos of --photos DIR (A_col.png or A.png .., any format OpenImageIO reads) or of the project;
// the project's held-out faces are not read (leave-one-face-out, fit/held_out_faces.hpp).
std::array<Image, 6> loadPhotos(const Project& project, const std::string& folder) {
  std::array<Image, 6> photos;
  int count = 0;
  for (FaceId face : kAllFaces) {
    if (project.heldOutFaces.contains(face)) continue;
    fs::path file = project.facePhotos[faceIndex(face)];
    if (!folder.empty()) {
      file.clear();
      const std::string letter(1, faceLetter(face));
      for (const char* suffix : {"_col.png", "_col.jpg", "_col.tif", ".png", ".jpg", ".tif"})
        if (fs::exists(fs::path(folder) / (letter + suffix))) {
          file = fs::path(folder) / (letter + suffix);
          break;
        }
    }
    if (file.empty()) continue;
    if (!fs::exists(file))
      throw InputError("the photo of face " + std::string(1, faceLetter(face)) +
                       " is missing: " + file.string());
    photos[faceIndex(face)] = readImage(file);
    ++count;
  }
  if (count == 0)
    throw InputError(folder.empty()
                         ? "the project has no face photos to infer the texture from; give --photos DIR"
                         : "no face photos (A_col.png .. F_col.png or A.png .. F.png) in " + folder);
  return photos;
}

// Photos (top row), the faces before (middle) and after (bottom) inference, A..F left to right.
Image comparisonSheet(const std::array<Image, 6>& photos, const std::array<Image, 6>& before,
                      const std::array<Image, 6>& after) {
  constexpr int kGap = 4;
  int slotW = 0, slotH = 0;
  for (const Image& p : photos) slotW = std::max(slotW, p.width), slotH = std::max(slotH, p.height);
  Image sheet(6 * slotW + 5 * kGap, 3 * slotH + 2 * kGap, 3);
  std::fill(sheet.pixels.begin(), sheet.pixels.end(), 1.0f);
  const std::array<const std::array<Image, 6>*, 3> rows{&photos, &before, &after};
  for (int row = 0; row < 3; ++row)
    for (int i = 0; i < 6; ++i) {
      const Image& image = (*rows[row])[i];
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
          std::copy_n(image.pixel(x, y), 3, sheet.pixel(i * (slotW + kGap) + x, row * (slotH + kGap) + y));
    }
  return sheet;
}

}  // namespace

Command addTextureCommand(CLI::App& app) {
  auto* texture = app.add_subcommand("texture",
                                     "Infer the texture detail (pores, rays, fibres, early-to-late "
                                     "transition) and colours of a project with a "
                                     "fitted growth field from its face photos (docs/texture.md)");
  struct Options {
    std::string project, out, photos, compare, parameters, appearance = "procedural";
    const TextureInferenceOptions defaults{};  // the core's defaults, stated once
    unsigned seed = defaults.loss.seed;
    int crops = defaults.loss.cropsPerFace, cropSize = defaults.loss.cropSize,
        sweeps = defaults.search.maxSweeps, samples = defaults.loss.samples,
        ringPhases = defaults.loss.ringPhaseBins;
    double flatTolerance = defaults.search.flatTolerance;
    bool coarse = defaults.coarseSearch, keepColours = false;
  };
  auto o = std::make_shared<Options>();
  texture->fallthrough();  // kerf-cli's own --stats, --threads, -q may also follow the subcommand
  texture
      ->add_option("PROJECT", o->project, "A project (.kerf; usually from `kerf-cli fit`) or a sample folder")
      ->required();
  texture->add_option("--out", o->out, "The project file to write (.kerf)")->required();
  texture->add_option(
      "--photos", o->photos,
      "Folder with the face photos A_col.png .. F_col.png (or A.png ..); default: the project's");
  cli::addNumber(texture, "--seed", o->seed,
                 "Where the compared crops lie (default " + std::to_string(o->seed) + ")");
  cli::addNumber(texture, "--crops", o->crops, "Crops per face (default " + std::to_string(o->crops) + ")", 1,
                 16);
  cli::addNumber(texture, "--crop-size", o->cropSize,
                 "Crop side in photo pixels (default " + std::to_string(o->cropSize) + ")", 16, 1024);
  cli::addNumber(texture, "--sweeps", o->sweeps,
                 "Coordinate-search sweeps (default " + std::to_string(o->sweeps) +
                     "; 0: none, only the coarse grid if on)",
                 0, 100);
  cli::addNumber(texture, "--flat-tolerance", o->flatTolerance,
                 "Settle a parameter whose two trials moved the loss by no more than this share of it "
                 "(default " +
                     std::to_string(o->flatTolerance) + "; 0: never, the step halves instead)",
                 0.0, 1.0);
  cli::addNumber(texture, "--samples", o->samples,
                 "Points per pixel side when rendering (default " + std::to_string(o->samples) + ")", 1, 4);
  texture->add_option("--params", o->parameters,
                      "Comma-separated detail parameters to search (default: all; e.g. "
                      "pores.radius_earlywood,rays.spacing)");
  cli::addNumber(texture, "--ring-phases", o->ringPhases,
                 "Also compare the statistics per part of the ring, in N ring phases (default 0: off)", 0, 8);
  texture
      ->add_option(
          "--appearance", o->appearance,
          "procedural (default): infer the procedural model's detail from the photos (tens of seconds). "
          "photo: "
          "make every surface of the project's own photos, re-grown along the fitted field (issue 17, "
          "docs/texture.md); stored in the project, used by render-faces, render-cut and export (colour "
          "volumes too); the "
          "procedural parameters are kept as they are")
      ->check(CLI::IsMember({"procedural", "photo"}));
  texture->add_flag(
      "--coarse,!--no-coarse", o->coarse,
      "Start with the coarse size grid: x0.5 / x1 / x2 the sizes of fibres, pores and rays (off by default; "
      "for a start whose pores, rays and fibres are far from the wood's)");
  texture->add_flag("--keep-colours", o->keepColours, "Do not refit the colours after the detail");
  texture->add_option("--compare", o->compare,
                      "Also write an image: photos (top), faces before (middle) and after (bottom), A..F");
  return {
      texture, [o](Context& context) {
        const fs::path input = o->project;
        if (!fs::exists(input)) throw InputError("no such project or sample folder: " + input.string());
        Project project = loadDocument(input);
        if (o->appearance == "photo") {
          if (!o->photos.empty())
            throw InputError(
                "--photos is not used with --appearance photo: the photo-true appearance is made from the "
                "project's own photos (its \"faces\")");
          if (!o->compare.empty())
            throw InputError("--compare is not used with --appearance photo; use render-faces");
          storePhotoAppearance(project);
          saveProject(project, o->out);
          std::printf("project written to %s\n", o->out.c_str());
          return;
        }
        project.appearance = Appearance::Procedural;
        const std::array<Image, 6> photos = loadPhotos(project, o->photos);
        TextureInferenceOptions options;
        options.loss.seed = o->seed;
        options.loss.cropsPerFace = o->crops;
        options.loss.cropSize = o->cropSize;
        options.loss.samples = o->samples;
        options.search.maxSweeps = o->sweeps;
        options.search.flatTolerance = o->flatTolerance;
        options.coarseSearch = o->coarse;
        options.refitColours = !o->keepColours;
        if (!o->parameters.empty()) {
          std::string list = o->parameters;
          std::replace(list.begin(), list.end(), ',', ' ');
          std::istringstream words(list);
          for (std::string id; words >> id;) options.parameters.push_back(id);
        }
        const WoodParameters fitted = project.params;
        inferProjectTexture(project, photos, options, context);
        if (!o->compare.empty()) {
          std::array<Image, 6> before, after;
          const GrowthRates rates = project.effectiveRates();
          const WoodModel beforeModel(project.block, fitted, rates);
          const WoodModel afterModel(project.block, project.params, rates);
          for (FaceId face : kAllFaces) {
            const Image& photo = photos[faceIndex(face)];
            if (photo.empty()) continue;
            before[faceIndex(face)] = renderFace(beforeModel, face, {photo.width, photo.height}, o->samples);
            after[faceIndex(face)] = renderFace(afterModel, face, {photo.width, photo.height}, o->samples);
          }
          writeImage(o->compare, comparisonSheet(photos, before, after));
          std::printf("comparison written to %s\n", o->compare.c_str());
        }
        saveProject(project, o->out);
        std::printf("project written to %s\n", o->out.c_str());
      }};
}

}  // namespace kerf::cli
