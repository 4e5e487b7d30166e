#include "texture/texture_objective.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "texture/shading_layers.hpp"
#include "util/parallel.hpp"

namespace kerf {
namespace {

double meanAbsoluteDifference(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(a.pixels[i] - b.pixels[i]);
  return a.pixels.empty() ? 0.0 : sum / a.pixels.size();
}

double blurredMeanAbsoluteDifference(const Image& a, const Image& b, double sigmaPx) {
  const cv::Mat ma(a.height, a.width, CV_32FC3, const_cast<float*>(a.pixels.data()));
  const cv::Mat mb(b.height, b.width, CV_32FC3, const_cast<float*>(b.pixels.data()));
  cv::Mat ba, bb, diff;
  cv::GaussianBlur(ma, ba, cv::Size(), sigmaPx, sigmaPx, cv::BORDER_REFLECT101);
  cv::GaussianBlur(mb, bb, cv::Size(), sigmaPx, sigmaPx, cv::BORDER_REFLECT101);
  cv::absdiff(ba, bb, diff);
  const cv::Scalar mean = cv::mean(diff);
  return (mean[0] + mean[1] + mean[2]) / 3.0;
}

// Which part of its ring every pixel of a crop lies in: the ring phase (Liu Sec. 4.2: 0 at the start of
// the earlywood, 1 at the ring boundary) of the fitted field at the pixel centre, in `bins` equal parts.
// The detail does not move the rings, so the labels hold for every candidate and for the photo.
std::vector<std::uint8_t> ringPhaseLabels(const WoodModel& model, const FaceCrop& crop, glm::ivec2 imageSize,
                                          int bins) {
  std::vector<std::uint8_t> labels(static_cast<std::size_t>(crop.width) * crop.height);
  const float offset = model.params().ringOffset;
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x) {
      const glm::vec3 p = model.block().pixelCenter(crop.face, crop.x + x, crop.y + y, imageSize);
      const float t = model.material().year(p) - offset;
      const float phase = t - std::floor(t);
      labels[static_cast<std::size_t>(y) * crop.width + x] =
          static_cast<std::uint8_t>(std::min(bins - 1, static_cast<int>(phase * bins)));
    }
  return labels;
}

// Pooled and per-ring-phase style distances of one face, half and half (only the pooled one without
// phases): the phases tell ring-porous wood (pores at the start of the ring) from diffuse-porous wood.
double faceStyle(const std::vector<TextureStatistics>& texture,
                 const std::vector<TextureStatistics>& target) {
  const double pooled = styleDistance(texture[0], target[0]).total;
  double sum = 0;
  int parts = 0;
  for (std::size_t i = 1; i < target.size(); ++i)
    if (!target[i].empty() && !texture[i].empty()) sum += styleDistance(texture[i], target[i]).total, ++parts;
  return parts ? 0.5 * pooled + 0.5 * sum / parts : pooled;
}

}  // namespace

TextureObjective::TextureObjective(const Block& block, const GrowthRates& rates, const WoodParameters& params,
                                   const std::array<Image, 6>& photos, const TextureLossOptions& options)
    : block_(block), rates_(rates), startParams_(params), options_(options), photos_(photos) {
  if (options.samples < 1 || options.samples > 8) throw InputError("samples per pixel side must be 1..8");
  layout_ = placeFaceCrops(block, photos, options.cropsPerFace, options.cropSize, options.seed);
  const WoodModel model(block, params, rates);
  for (FaceId face : kAllFaces)
    orientations_[faceIndex(face)] = faceOrientation(block, face, model.field().axis());
  for (std::size_t k = 0; k < layout_.crops.size(); ++k) {
    const FaceCrop& crop = layout_.crops[k];
    photoCrops_.push_back(cropImage(photos[faceIndex(crop.face)], crop));
    photoGrain_.push_back(grainViewOf(photoCrops_.back(), layout_.pxPerMm[faceIndex(crop.face)]));
    cropsOfFace_[faceIndex(crop.face)].push_back(k);
    if (options.ringPhaseBins > 0)
      cropLabels_.push_back(
          ringPhaseLabels(model, crop, layout_.imageSize[faceIndex(crop.face)], options.ringPhaseBins));
    if (options.bandWeight > 0 && options.bandBins > 0) {  // only the search uses the crops' profiles
      bandLabels_.push_back(
          ringPhaseLabels(model, crop, layout_.imageSize[faceIndex(crop.face)], options.bandBins));
      photoBand_[faceIndex(crop.face)].add(ringBandProfile(
          photoCrops_.back(), bandLabels_.back(), options.bandBins, layout_.pxPerMm[faceIndex(crop.face)]));
    }
  }
  cropLocations_.resize(layout_.crops.size());
  parallelRows(static_cast<int>(layout_.crops.size()), [&](int k) {
    const FaceCrop& crop = layout_.crops[k];
    cropLocations_[k] = locateFaceCrop(model, crop, layout_.imageSize[faceIndex(crop.face)], options.samples);
  });
  for (const FaceCrop& crop : layout_.crops) {  // the corners and the centre of every crop
    const glm::ivec2 size = layout_.imageSize[faceIndex(crop.face)];
    for (const glm::vec2 at :
         {glm::vec2(crop.x, crop.y), glm::vec2(crop.x + crop.width, crop.y),
          glm::vec2(crop.x, crop.y + crop.height), glm::vec2(crop.x + crop.width, crop.y + crop.height),
          glm::vec2(crop.x + 0.5f * crop.width, crop.y + 0.5f * crop.height)}) {
      probes_.push_back(block.imageToBlock(crop.face, at, size));
      probeLocations_.push_back(model.material().locate(probes_.back()));
    }
  }
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    if (cropsOfFace_[i].empty()) continue;
    std::vector<Image> crops;
    std::vector<std::vector<std::uint8_t>> labels;
    for (std::size_t k : cropsOfFace_[i]) {
      crops.push_back(photoCrops_[k]);
      if (!cropLabels_.empty()) labels.push_back(cropLabels_[k]);
    }
    photoStatistics_[i] = computeLabelledTextureStatistics(crops, labels, options.ringPhaseBins,
                                                           layout_.pxPerMm[i], options.statistics);
  }
}

// Whether the model puts the probe points exactly where the start parameters did: then it does so
// everywhere (the texture parameters never move a point; the test TextureObjective.
// ReusesLocationsOnlyWhereTheyHold checks the whole search space), and the stored crop locations hold.
bool TextureObjective::sameLocations(const WoodModel& model) const {
  for (std::size_t i = 0; i < probes_.size(); ++i) {
    const WoodLocation a = model.material().locate(probes_[i]), &b = probeLocations_[i];
    if (a.year != b.year || a.knotDarkness != b.knotDarkness || a.knotShade != b.knotShade ||
        a.c.height != b.c.height || a.c.radius != b.c.radius || a.c.azimuth != b.c.azimuth ||
        a.c.x != b.c.x || a.c.y != b.c.y)
      return false;
  }
  return true;
}

Image TextureObjective::renderCrop(const WoodModel& model, bool located, std::size_t k) const {
  const FaceCrop& crop = layout_.crops[k];
  return located ? renderFaceCrop(model, crop, cropLocations_[k], options_.samples)
                 : renderFaceCrop(model, crop, layout_.imageSize[faceIndex(crop.face)], options_.samples);
}

double TextureObjective::combine(const std::array<FaceTextureScore, 6>& faces) const {
  double end = 0, side = 0;
  int endCount = 0, sideCount = 0;
  for (int i = 0; i < 6; ++i) {
    if (!faces[i].used) continue;
    const double face = faces[i].style + options_.l1Weight * faces[i].l1 +
                        options_.grainWeight * (1.0 - faces[i].grain) +
                        options_.contrastWeight * std::abs(std::log(std::max(faces[i].contrast, 1e-3))) +
                        options_.figureWeight * (1.0 - faces[i].figure) + options_.bandWeight * faces[i].band;
    // Streak length only on side grain, where the lines are the fibres and the pores cut along them; on
    // end grain they are the rings, whose continuity the figure term already judges.
    if (orientations_[i].grain == FaceGrain::EndGrain)
      end += face, ++endCount;
    else
      side += face + options_.streakWeight * faces[i].streak, ++sideCount;
  }
  const int groups = (endCount > 0) + (sideCount > 0);
  return ((endCount ? end / endCount : 0.0) + (sideCount ? side / sideCount : 0.0)) / std::max(1, groups);
}

std::vector<TextureScore> TextureObjective::evaluate(const std::vector<WoodParameters>& candidates,
                                                     const Progress& progress) const {
  std::vector<std::unique_ptr<WoodModel>> models;
  for (const WoodParameters& params : candidates)
    models.push_back(std::make_unique<WoodModel>(block_, params, rates_));
  // Candidates that put the crops' points where the start did share their layers (texture/
  // shading_layers.hpp); the others are rendered from scratch.
  std::vector<const WoodModel*> located;
  std::vector<std::size_t> unlocated;
  for (std::size_t c = 0; c < models.size(); ++c)
    if (sameLocations(*models[c]))
      located.push_back(models[c].get());
    else
      unlocated.push_back(c);
  const std::size_t crops = layout_.crops.size();
  std::vector<Image> rendered(candidates.size() * crops);
  std::vector<Image> shared = renderCandidateCrops(
      located, layout_.crops, cropLocations_, options_.samples, &counts_,
      progress.part(0.0, 0.8 * located.size() / std::max<std::size_t>(1, models.size())));
  for (std::size_t c = 0, i = 0, u = 0; c < models.size(); ++c) {
    if (u < unlocated.size() && unlocated[u] == c) {
      ++u;
      continue;
    }
    for (std::size_t k = 0; k < crops; ++k) rendered[c * crops + k] = std::move(shared[i * crops + k]);
    ++i;
  }
  // One work item per (candidate, crop): enough of them to keep every thread busy.
  parallelRows(
      static_cast<int>(unlocated.size() * crops),
      [&](int item) {
        const std::size_t c = unlocated[item / crops], k = item % crops;
        rendered[c * crops + k] = renderCrop(*models[c], false, k);
        counts_.composed += static_cast<std::uint64_t>(layout_.crops[k].width) * layout_.crops[k].height *
                            options_.samples * options_.samples;
      },
      progress.part(0.8 * located.size() / std::max<std::size_t>(1, models.size()), 0.8));
  std::vector<TextureScore> scores(candidates.size());
  parallelRows(
      static_cast<int>(candidates.size() * 6),
      [&](int item) {
        const std::size_t c = item / 6;
        const int face = item % 6;
        if (cropsOfFace_[face].empty()) return;
        std::vector<Image> faceCrops;
        std::vector<std::vector<std::uint8_t>> labels;
        double l1 = 0, grain = 0, contrast = 0, figure = 0, streak = 0;
        RingBandProfile band;
        for (std::size_t k : cropsOfFace_[face]) {
          if (options_.bandWeight > 0 && !bandLabels_.empty())
            band.add(ringBandProfile(rendered[c * crops + k], bandLabels_[k], options_.bandBins,
                                     layout_.pxPerMm[face]));
          faceCrops.push_back(rendered[c * crops + k]);
          if (!cropLabels_.empty()) labels.push_back(cropLabels_[k]);
          l1 += meanAbsoluteDifference(rendered[c * crops + k], photoCrops_[k]);
          const GrainView view = grainViewOf(rendered[c * crops + k], layout_.pxPerMm[face]);
          grain += grainAgreement(view, photoGrain_[k]);
          contrast += contrastRatio(view, photoGrain_[k]);
          figure += figureCorrelation(view, photoGrain_[k]);
          streak += streakDifference(view, photoGrain_[k]);
        }
        FaceTextureScore& score = scores[c].faces[face];
        const double count = static_cast<double>(cropsOfFace_[face].size());
        score.used = true;
        score.l1 = l1 / count;
        score.grain = grain / count;
        score.contrast = contrast / count;
        score.figure = figure / count;
        score.streak = streak / count;
        if (options_.bandWeight > 0) score.band = ringBandDifference(band, photoBand_[face]);
        score.style = faceStyle(computeLabelledTextureStatistics(faceCrops, labels, options_.ringPhaseBins,
                                                                 layout_.pxPerMm[face], options_.statistics),
                                photoStatistics_[face]);
      },
      progress.part(0.8, 1.0));
  for (TextureScore& score : scores) score.loss = combine(score.faces);
  return scores;
}

std::array<glm::vec3, 6> TextureObjective::meanColourRatios(const WoodParameters& params,
                                                            const Progress& progress) const {
  const WoodModel model(block_, params, rates_);
  const bool located = sameLocations(model);
  std::vector<Image> rendered(layout_.crops.size());
  parallelRows(
      static_cast<int>(rendered.size()), [&](int k) { rendered[k] = renderCrop(model, located, k); },
      progress);
  std::array<glm::dvec3, 6> photoSum{}, renderSum{};
  for (std::size_t k = 0; k < rendered.size(); ++k) {
    const int face = faceIndex(layout_.crops[k].face);
    const std::vector<float>&a = photoCrops_[k].pixels, &b = rendered[k].pixels;
    for (std::size_t i = 0; i < a.size(); ++i) photoSum[face][i % 3] += a[i], renderSum[face][i % 3] += b[i];
  }
  std::array<glm::vec3, 6> ratios;
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c)
      ratios[f][c] = renderSum[f][c] > 1e-9 ? static_cast<float>(photoSum[f][c] / renderSum[f][c]) : 1.0f;
  return ratios;
}

TextureScore TextureObjective::evaluateFullFaces(const WoodParameters& params,
                                                 const Progress& progress) const {
  return evaluateFullFaces(std::vector<WoodParameters>{params}, progress)[0];
}

std::vector<TextureScore> TextureObjective::evaluateFullFaces(const std::vector<WoodParameters>& candidates,
                                                              const Progress& progress) const {
  const WoodModel start(block_, startParams_, rates_);  // the ring phases, as for the crops
  std::vector<std::unique_ptr<WoodModel>> models;
  std::vector<const WoodModel*> located;  // their faces share locations and layers (shading_layers.hpp)
  std::vector<std::size_t> locatedIndex, unlocated;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    models.push_back(std::make_unique<WoodModel>(block_, candidates[c], rates_));
    if (sameLocations(*models.back()))
      located.push_back(models.back().get()), locatedIndex.push_back(c);
    else
      unlocated.push_back(c);
  }
  constexpr int kStripRows = 8;  // a face is rendered in strips: work items for every thread
  std::vector<TextureScore> scores(candidates.size());
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    if (cropsOfFace_[i].empty()) continue;
    const Progress part = progress.part(i / 6.0, (i + 1) / 6.0);
    const Image& photo = photos_[i];
    const glm::ivec2 size = layout_.imageSize[i];
    std::vector<Image> images(candidates.size());
    if (!located.empty()) {
      std::vector<FaceCrop> strips;
      for (int y = 0; y < size.y; y += kStripRows)
        strips.push_back(FaceCrop{face, 0, y, size.x, std::min(kStripRows, size.y - y)});
      std::vector<std::vector<WoodLocation>> where(strips.size());
      parallelRows(
          static_cast<int>(strips.size()),
          [&](int k) { where[k] = locateFaceCrop(start, strips[k], size, options_.samples); },
          part.part(0.0, 0.3));
      const std::vector<Image> rendered =
          renderCandidateCrops(located, strips, where, options_.samples, nullptr, part.part(0.3, 0.7));
      for (std::size_t j = 0; j < located.size(); ++j) {
        Image image(size.x, size.y, 3);
        for (std::size_t k = 0; k < strips.size(); ++k) {
          const std::vector<float>& rows = rendered[j * strips.size() + k].pixels;
          std::copy(rows.begin(), rows.end(), image.pixel(0, strips[k].y));
        }
        images[locatedIndex[j]] = std::move(image);
      }
    }
    for (std::size_t c : unlocated) images[c] = renderFace(*models[c], face, size, options_.samples);
    std::vector<std::vector<std::uint8_t>> labels;
    if (options_.ringPhaseBins > 0)
      labels.push_back(
          ringPhaseLabels(start, FaceCrop{face, 0, 0, size.x, size.y}, size, options_.ringPhaseBins));
    const auto statsOf = [&](const Image& im) {
      return computeLabelledTextureStatistics(std::span<const Image>(&im, 1), labels, options_.ringPhaseBins,
                                              layout_.pxPerMm[i], options_.statistics);
    };
    const std::vector<TextureStatistics> photoStats = statsOf(photo);
    const GrainView photoView = grainViewOf(photo, layout_.pxPerMm[i]);
    std::vector<std::uint8_t> bandLabels;
    RingBandProfile photoBand;
    if (options_.bandBins > 0) {
      bandLabels = ringPhaseLabels(start, FaceCrop{face, 0, 0, size.x, size.y}, size, options_.bandBins);
      photoBand = ringBandProfile(photo, bandLabels, options_.bandBins, layout_.pxPerMm[i]);
    }
    parallelRows(
        static_cast<int>(candidates.size()),
        [&](int c) {
          const Image& image = images[c];
          const GrainView view = grainViewOf(image, layout_.pxPerMm[i]);
          const double band =
              options_.bandBins > 0
                  ? ringBandDifference(
                        ringBandProfile(image, bandLabels, options_.bandBins, layout_.pxPerMm[i]), photoBand)
                  : 0.0;
          scores[c].faces[i] = {true,
                                faceStyle(statsOf(image), photoStats),
                                meanAbsoluteDifference(image, photo),
                                blurredMeanAbsoluteDifference(image, photo, layout_.pxPerMm[i]),
                                grainAgreement(view, photoView),
                                contrastRatio(view, photoView),
                                figureCorrelation(view, photoView),
                                streakDifference(view, photoView),
                                band};
        },
        part.part(0.7, 1.0));
  }
  for (TextureScore& score : scores) score.loss = combine(score.faces);
  return scores;
}

}  // namespace kerf
