#include "appearance/photo_true_appearance.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "appearance/surface_grid.hpp"
#include "io/project.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

// Photos' proportions within 2 % (+1 px) of their face's, as the texture inference asks.
void checkProportions(const Block& block, FaceId face, const Image& photo) {
  const FaceFrame frame = block.face(face);
  const float expected = frame.heightMm * photo.width / frame.widthMm;
  if (std::abs(photo.height - expected) > 0.02f * expected + 1.0f)
    throw InputError("the photo of face " + std::string(1, faceLetter(face)) + " is " +
                     std::to_string(photo.width) + " x " + std::to_string(photo.height) +
                     " px, but the face is " + std::to_string(frame.widthMm) + " x " +
                     std::to_string(frame.heightMm) + " mm: its proportions differ from the face's");
}

float bilinear(const Image& image, float x, float y, int c) {
  x = std::clamp(x, 0.0f, image.width - 1.0f);
  y = std::clamp(y, 0.0f, image.height - 1.0f);
  const int x0 = std::min(static_cast<int>(x), std::max(image.width - 2, 0));
  const int y0 = std::min(static_cast<int>(y), std::max(image.height - 2, 0));
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const float fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * image.pixel(x0, y0)[c] + fx * image.pixel(x1, y0)[c]) +
         fy * ((1 - fx) * image.pixel(x0, y1)[c] + fx * image.pixel(x1, y1)[c]);
}

// `source` (whose pixels are `ratio` times as dense as the output's, per axis, same top-left corner) into
// the first three channels of `out`: bilinear, averaged over the output pixel's footprint when shrinking.
void resampleInto(const Image& source, glm::vec2 ratio, Image& out) {
  const int nx = std::max(1, static_cast<int>(std::ceil(ratio.x - 1e-3f)));
  const int ny = std::max(1, static_cast<int>(std::ceil(ratio.y - 1e-3f)));
  parallelRows(out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      float sum[3] = {0, 0, 0};
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const float sx = (x + (i + 0.5f) / nx) * ratio.x - 0.5f,
                      sy = (y + (j + 0.5f) / ny) * ratio.y - 0.5f;
          for (int c = 0; c < 3; ++c) sum[c] += bilinear(source, sx, sy, c);
        }
      for (int c = 0; c < 3; ++c) out.pixel(x, y)[c] = sum[c] / (nx * ny);
    }
  });
}

// The photos of a block differ in white balance and exposure from face to face (Mokume A.2.3 fits a tint
// per face for it); patches from several photos side by side would show it as blotches. Each photo's
// channels are scaled so that its mean is the mean over all photos: the tint of no face in particular.
void equaliseTints(std::vector<Exemplar>& exemplars) {
  std::vector<glm::dvec3> means;
  glm::dvec3 overall(0.0);
  for (const Exemplar& e : exemplars) {
    glm::dvec3 sum(0.0);
    for (int y = 0; y < e.colour.height; ++y)
      for (int x = 0; x < e.colour.width; ++x)
        sum += glm::dvec3(e.colour.pixel(x, y)[0], e.colour.pixel(x, y)[1], e.colour.pixel(x, y)[2]);
    means.push_back(sum / double(e.colour.width * e.colour.height));
    overall += means.back() / double(exemplars.size());
  }
  for (std::size_t i = 0; i < exemplars.size(); ++i) {
    const glm::dvec3 gain = overall / glm::max(means[i], glm::dvec3(1e-6));
    Image& c = exemplars[i].colour;
    for (std::size_t k = 0; k < c.pixels.size(); ++k)
      c.pixels[k] = std::min(1.0f, float(c.pixels[k] * gain[int(k % 3)]));
  }
}

std::uint32_t mixSeed(std::uint32_t seed, std::uint32_t salt) {
  std::uint32_t h = seed * 0x9E3779B1u ^ (salt + 0x7F4A7C15u + (seed << 6) + (seed >> 2));
  h ^= h >> 16;
  h *= 0x85EBCA6Bu;
  h ^= h >> 13;
  return h;
}

std::uint32_t planeSalt(const CutPlane& plane, float pxPerMm) {
  std::uint32_t h = 0x1234567u;
  for (float v : {plane.point().x, plane.point().y, plane.point().z, plane.normal().x, plane.normal().y,
                  plane.normal().z, pxPerMm}) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h = mixSeed(h, bits);
  }
  return h;
}

}  // namespace

PhotoTrueAppearance::PhotoTrueAppearance(const WoodModel& model, std::array<Image, 6> photos,
                                         const FaceSet& heldOut, const PhotoTrueOptions& options,
                                         const Progress& progress)
    : model_(model), options_(options) {
  const Block& block = model.block();
  std::vector<float> densities;
  for (FaceId face : kAllFaces) {
    const Image& photo = photos[faceIndex(face)];
    if (photo.empty() || heldOut.contains(face)) continue;  // leave-one-face-out: never an exemplar
    checkProportions(block, face, photo);
    faces_.push_back(face);
    densities.push_back(photo.width / block.face(face).widthMm);
  }
  if (faces_.empty())
    throw InputError(
        heldOut.empty() ? "the photo-true appearance needs face photos, and there are none"
                        : "the photo-true appearance needs face photos, and every face with one is held out");
  // One synthesis resolution: the photos' median; a photo at another resolution is resampled to it.
  std::vector<float> sorted = densities;
  std::sort(sorted.begin(), sorted.end());
  pxPerMm_ = sorted[sorted.size() / 2];
  std::vector<Exemplar> exemplars;
  for (std::size_t i = 0; i < faces_.size(); ++i) {
    progress.throwIfCancelled();
    const FaceId face = faces_[i];
    Image& photo = photos[faceIndex(face)];
    Exemplar exemplar;
    const glm::ivec2 size = block.faceImageSize(face, pxPerMm_);
    if (std::abs(densities[i] / pxPerMm_ - 1.0f) < 0.01f && size == glm::ivec2(photo.width, photo.height)) {
      exemplar.colour = std::move(photo);
    } else {
      exemplar.colour = Image(size.x, size.y, 3);
      resampleInto(photo, {float(photo.width) / size.x, float(photo.height) / size.y}, exemplar.colour);
      photo = Image{};
    }
    exemplar.guidance = computeGuidance(model, faceGrid(block, face, size), options.weights);
    exemplars.push_back(std::move(exemplar));
    progress.set(double(i + 1) / faces_.size());
  }
  equaliseTints(exemplars);
  exemplars_ = prepareExemplars(std::move(exemplars), options.synthesis);
}

Image PhotoTrueAppearance::renderFace(FaceId face, glm::ivec2 size, const Progress& progress) const {
  checkImageSize(size, "the image of face " + std::string(1, faceLetter(face)));
  const Block& block = model_.block();
  const glm::ivec2 synthSize = block.faceImageSize(face, pxPerMm_);
  GuidedSynthesisOptions synthesis = options_.synthesis;
  synthesis.seed = mixSeed(options_.synthesis.seed, 101u + faceIndex(face));
  // A photographed face's own levels are its exemplar's (the same guidance on the same grid).
  const auto exemplar = std::find(faces_.begin(), faces_.end(), face);
  const Image synthesised =
      exemplar != faces_.end()
          ? synthesizeGuided(*exemplars_, static_cast<int>(exemplar - faces_.begin()), synthesis, progress)
          : synthesizeGuided(*exemplars_,
                             computeGuidance(model_, faceGrid(block, face, synthSize), options_.weights,
                                             progress.part(0.0, 0.1)),
                             synthesis, progress.part(0.1, 1.0));
  if (synthSize == size) return synthesised;
  Image out(size.x, size.y, 3);
  resampleInto(synthesised, {float(synthSize.x) / size.x, float(synthSize.y) / size.y}, out);
  return out;
}

std::array<Image, 6> PhotoTrueAppearance::renderFaces(float pxPerMm, const Progress& progress) const {
  if (!(pxPerMm > 0.0f) || !std::isfinite(pxPerMm))
    throw InputError("pixels per mm must be a positive number");
  std::array<Image, 6> images;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    images[i] =
        renderFace(face, model_.block().faceImageSize(face, pxPerMm), progress.part(i / 6.0, (i + 1) / 6.0));
  }
  return images;
}

Image PhotoTrueAppearance::renderCut(const CutPlane& plane, float pxPerMm, const Progress& progress) const {
  const Block& block = model_.block();
  const SurfaceGrid outGrid = cutGrid(block, plane, pxPerMm);  // checks the plane and the size
  const SurfaceGrid grid = cutGrid(block, plane, pxPerMm_);
  const SurfaceGuidance guidance = computeGuidance(model_, grid, options_.weights, progress.part(0.0, 0.1));
  GuidedSynthesisOptions synthesis = options_.synthesis;
  synthesis.seed = mixSeed(options_.synthesis.seed, planeSalt(plane, pxPerMm));
  const Image synthesised = synthesizeGuided(*exemplars_, guidance, synthesis, progress.part(0.1, 0.95));
  Image out(outGrid.width, outGrid.height, 4);
  resampleInto(synthesised, glm::vec2(pxPerMm_ / pxPerMm), out);
  // Coverage as renderCut computes it with 2 x 2 points per pixel: transparent outside the block.
  parallelRows(out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      int inside = 0;
      for (int sy = 0; sy < 2; ++sy)
        for (int sx = 0; sx < 2; ++sx)
          inside +=
              block.contains(outGrid.point(x - 0.5f + (sx + 0.5f) / 2, y - 0.5f + (sy + 0.5f) / 2)) ? 1 : 0;
      float* p = out.pixel(x, y);
      p[3] = inside / 4.0f;
      if (inside == 0) p[0] = p[1] = p[2] = 0.0f;
    }
  });
  return out;
}

Image PhotoTrueAppearance::renderGrid(const SurfaceGrid& grid, std::uint32_t salt,
                                      const Progress& progress) const {
  checkImageSize({grid.width, grid.height}, "the image of the surface");
  // The same rectangle at the photos' resolution: its corner, pixel (-0.5, -0.5), stays where it is.
  const glm::vec2 mm(grid.width * glm::length(grid.right), grid.height * glm::length(grid.down));
  SurfaceGrid synth = grid;
  synth.width = std::max(1, static_cast<int>(std::lround(mm.x * pxPerMm_)));
  synth.height = std::max(1, static_cast<int>(std::lround(mm.y * pxPerMm_)));
  synth.right = grid.right * (float(grid.width) / synth.width);
  synth.down = grid.down * (float(grid.height) / synth.height);
  synth.origin = grid.point(-0.5f, -0.5f) + 0.5f * (synth.right + synth.down);
  const SurfaceGuidance guidance = computeGuidance(model_, synth, options_.weights, progress.part(0.0, 0.1));
  const Image synthesised = renderGuidance(guidance, salt, progress.part(0.1, 1.0));
  if (synth.width == grid.width && synth.height == grid.height) return synthesised;
  Image out(grid.width, grid.height, 3);
  resampleInto(synthesised, {float(synth.width) / grid.width, float(synth.height) / grid.height}, out);
  return out;
}

Image PhotoTrueAppearance::renderGuidance(const SurfaceGuidance& guidance, std::uint32_t salt,
                                          const Progress& progress) const {
  GuidedSynthesisOptions synthesis = options_.synthesis;
  synthesis.seed = mixSeed(options_.synthesis.seed, salt);
  return synthesizeGuided(*exemplars_, guidance, synthesis, progress);
}

std::array<Image, 6> loadAppearancePhotos(const Project& project) {
  return loadAppearancePhotos(project.facePhotos, project.heldOutFaces);
}

std::array<Image, 6> loadAppearancePhotos(const std::array<std::filesystem::path, 6>& facePhotos,
                                          const FaceSet& heldOut) {
  std::array<Image, 6> photos;
  int count = 0;
  for (FaceId face : kAllFaces) {
    const std::filesystem::path& file = facePhotos[faceIndex(face)];
    if (file.empty() || heldOut.contains(face)) continue;
    if (!std::filesystem::exists(file))
      throw InputError("the photo of face " + std::string(1, faceLetter(face)) +
                       " is missing: " + file.string());
    photos[faceIndex(face)] = readImage(file);
    ++count;
  }
  if (count == 0)
    throw InputError(
        heldOut.empty()
            ? "the project has no face photos: the photo-true appearance is made from them"
            : "the project has no face photos besides its held-out faces: the photo-true appearance "
              "is made from them");
  return photos;
}

}  // namespace kerf
