// fit: infer the growth field from a sample's ring-localization images (Mokume Sec. 5.2: step 1, the
// pith axis of an undeformed field and the ring width and phase along it; step 2, the growth rates R)
// and write a project.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <optional>

#include "command.hpp"
#include "field/growth_field.hpp"
#include "fit/anatomy_prior.hpp"
#include "fit/distortion_fit.hpp"
#include "fit/iso_contour_loss.hpp"
#include "fit/iso_contours.hpp"
#include "fit/pith_fit.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "util/error.hpp"

namespace kerf::cli {

namespace fs = std::filesystem;

namespace {

// X_arl-unet.png first, else any X_arl*.png (sorted by name, so the choice is stable).
fs::path findRingImage(const fs::path& folder, FaceId face) {
  const std::string prefix = std::string(1, faceLetter(face)) + "_arl";
  const fs::path preferred = folder / (prefix + "-unet.png");
  if (fs::exists(preferred)) return preferred;
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.rfind(prefix, 0) == 0 && entry.path().extension() == ".png")
      found.push_back(entry.path());
  }
  std::sort(found.begin(), found.end());
  return found.empty() ? fs::path() : found.front();
}

void printCandidate(const char* label, const PithCandidate& c, float ringWidthMm) {
  std::printf(
      "%s: O = (%.3f, %.3f, %.3f) mm, V = (%.5f, %.5f, %.5f) (tilt %.2f deg, azimuth %.2f deg), "
      "distance from the block centre %.1f mm\n",
      label, c.axis.origin.x, c.axis.origin.y, c.axis.origin.z, c.axis.direction.x, c.axis.direction.y,
      c.axis.direction.z, c.tiltDeg, c.azimuthDeg, glm::length(c.axis.origin));
  std::printf(
      "  iso-contour loss: %.4f mm = %.4f ring spacings (mean over faces); authors' form 10*sum/40 = %.6f\n",
      c.loss.meanOverFaces, ringWidthMm > 0 ? c.loss.meanOverFaces / ringWidthMm : 0.0,
      mokumeLoggedLoss(c.loss));
}

}  // namespace

Command addFitCommand(CLI::App& app) {
  auto* fit = app.add_subcommand("fit",
                                 "Fit the growth field (pith axis, ring width and phase) to a sample's "
                                 "ring-localization images (X_arl*.png)");
  struct Options {
    std::string sample, out, principal = "y";
    bool pithOnly = false;
    bool ignoreAnatomy = false;
    double anatomyWeight = 1.0;
  };
  auto o = std::make_shared<Options>();
  fit->add_option("SAMPLE", o->sample, "A Mokume-style sample folder with A_arl-unet.png .. F_arl-unet.png")
      ->required();
  fit->add_option("--out", o->out, "The project file to write (.kerf)")->required();
  fit->add_option("--principal", o->principal,
                  "Expected pith direction: the block axis x, y or z (default y)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  fit->add_flag("--pith-only", o->pithOnly, "Step 1 only: no growth-rate (distortion) fit; uniform rates");
  fit->add_flag("--ignore-anatomy", o->ignoreAnatomy,
                "Fit the pith to the ring contours alone; the fibre direction seen in the photos (X_col.png) "
                "is still reported");
  fit->add_option("--anatomy-weight", o->anatomyWeight,
                  "Strength of the anatomical prior on the pith direction (default 1; 0 = report only)")
      ->check(CLI::Range(0.0, 100.0));
  return {
      fit, [o](Context& context) {
        const fs::path folder = o->sample;
        if (!fs::is_directory(folder)) throw InputError("not a sample folder: " + folder.string());
        Project project;  // without photos, the ring images alone are enough to fit
        try {
          project = projectFromSampleFolder(folder);
        } catch (const InputError&) {
        }
        const Block& block = project.block;

        const Stopwatch extractClock;
        std::array<GrayImage8, 6> images;
        IsoContours contours;
        for (FaceId face : kAllFaces) {
          const fs::path file = findRingImage(folder, face);
          if (file.empty()) {
            std::fprintf(stderr,
                         "kerf-cli: warning: face %c has no ring-localization image (%c_arl*.png); "
                         "skipped\n",
                         faceLetter(face), faceLetter(face));
            continue;
          }
          GrayImage8& image = images[faceIndex(face)];
          image = readRingLocalizationImage(file);
          const auto pixels = extractIsoContours(image);
          addFaceContours(contours, block, face, {image.width, image.height}, pixels);
          std::printf("face %c: %zu contours from %s\n", faceLetter(face), pixels.size(),
                      file.filename().string().c_str());
        }
        const double extractSeconds = extractClock.seconds();

        PithFitOptions options;
        options.principal = o->principal == "x"   ? glm::vec3(1, 0, 0)
                            : o->principal == "z" ? glm::vec3(0, 0, 1)
                                                  : glm::vec3(0, 1, 0);
        // Anatomical prior (fit/anatomy_prior.hpp): the fibre direction from the face photos' texture.
        std::optional<AnatomyEstimate> anatomy;
        {
          std::array<Image, 6> photos;
          int found = 0;
          for (FaceId face : kAllFaces) {
            const fs::path file = folder / (std::string(1, faceLetter(face)) + "_col.png");
            if (!fs::exists(file)) continue;
            photos[faceIndex(face)] = readImage(file);
            ++found;
          }
          if (found > 0) {
            anatomy = estimateFibreDirection(photos, block);
            std::printf(
                "anatomy: fibre direction from the texture of %d face photos F = (%.3f, %.3f, %.3f), "
                "confidence %.3f%s\n",
                anatomy->facesUsed, anatomy->fibre.x, anatomy->fibre.y, anatomy->fibre.z, anatomy->confidence,
                o->ignoreAnatomy || o->anatomyWeight <= 0 ? " (not used by the fit)" : " (used as a prior)");
          } else {
            std::printf("anatomy: no face photos (X_col.png); the pith is fitted to the contours alone\n");
          }
        }
        if (anatomy && !o->ignoreAnatomy) {
          options.anatomy = anatomy;
          options.anatomyWeight = o->anatomyWeight;
        }
        const PithFitResult result = fitPith(contours, block, options, context.progress());
        for (const std::string& w : result.warnings)
          std::fprintf(stderr, "kerf-cli: warning: %s\n", w.c_str());

        const Stopwatch ringClock;
        const RingLevelEstimate rings = estimateRingLevels(result.best.axis, block, images);
        const double ringSeconds = ringClock.seconds();

        std::printf("%d contours, %d points (%d used by the continuous fit), %d grid candidates\n",
                    result.contours, result.points, result.fitPoints, result.gridCandidates);
        printCandidate("pith", result.best, rings.ringWidthMm);
        if (anatomy) {
          const double angle = anatomyAngleDeg(*anatomy, result.best.axis.direction);
          std::printf("anatomy: the pith axis is %.1f deg from the fibre direction: %s\n", angle,
                      angle <= 20.0 ? "agrees"
                      : anatomy->confidence < 0.1f
                          ? "disagrees, but the fibre estimate is weak"
                          : "DISAGREES - the contours favour an axis the wood anatomy contradicts");
        }
        std::printf("rings: width %.4f mm, phase %.4f (%zu rings found, median spacing %.4f mm)\n",
                    rings.ringWidthMm, rings.ringOffset, rings.peaksMm.size(), rings.medianSpacingMm);
        if (result.flipped) {
          std::printf("ambiguity (Mokume B.1): %s\n",
                      result.ambiguous ? "AMBIGUOUS - the mirrored pith explains the rings almost as well"
                                       : "the mirrored pith is clearly worse");
          printCandidate("  other candidate", *result.flipped, rings.ringWidthMm);
        } else {
          std::printf("ambiguity (Mokume B.1): none (the mirrored start converged to the same axis)\n");
        }
        std::printf("time: contours %.3f s, grid search %.3f s, refinement %.3f s, rings %.3f s\n",
                    extractSeconds, result.gridSeconds, result.refineSeconds, ringSeconds);
        project.params.pithOrigin = result.best.axis.origin;
        project.params.pithTilt = result.best.tiltDeg;
        project.params.pithAzimuth = result.best.azimuthDeg;
        project.params.ringWidth = rings.ringWidthMm;
        project.params.ringOffset = rings.ringOffset;
        // The axis exactly as the project will rebuild it from its parameters.
        const PithAxis axis = PithAxis::fromAngles(project.params.pithOrigin, project.params.pithTilt,
                                                   project.params.pithAzimuth);
        project.rates = GrowthRates::uniform(block, axis);
        if (o->pithOnly) {
          std::printf("distortions (Mokume Eq. 4-6) not fitted (--pith-only): uniform growth rates\n");
        } else {
          const DistortionFitResult d =
              fitDistortions(contours, block, axis, rings.ringWidthMm, {}, context.progress());
          const GrowthField field(axis, rings.ringWidthMm, d.rates);
          const float width0 = rings.ringWidthMm;
          const RingLevelEstimate fitted = estimateRingLevels(
              [&field, width0](glm::vec3 p) { return static_cast<double>(field.evaluate(p)) * width0; },
              block, images);
          // Rings at whole years (Kerf's ring levels), from the peaks along the fitted field.
          std::vector<double> levels;
          for (float peak : fitted.peaksMm) levels.push_back(peak / width0);
          GrowthRates rates = remapRingsToWholeYears(d.rates, width0, levels);
          // Rates scaled to a median of 1 and the ring width with them (G unchanged), so growth.ring_width
          // stays the typical ring width in mm.
          std::vector<float> sorted = rates.rates;
          std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
          const float median = sorted[sorted.size() / 2];
          for (float& r : rates.rates) r /= median;
          project.rates = rates;
          project.params.ringWidth = width0 / median;
          project.params.ringOffset = 0.0f;
          const GrowthField saved(axis, project.params.ringWidth, rates);
          const IsoContourLoss finalLoss = isoContourLoss(contours, saved, 1.0);
          const double toRings = width0 / fitted.ringWidthMm;  // rings per year of the fitted field
          std::printf(
              "distortions (Mokume Eq. 4): %d x %d x %d rates, iso-contour loss %.4f -> %.4f ring spacings "
              "(mean over faces), %d iterations, %.3f s\n",
              d.rates.heights, d.rates.azimuths, d.rates.radii, d.lossBefore.meanOverFaces,
              d.lossAfter.meanOverFaces * toRings, d.iterations, d.seconds);
          std::printf(
              "rings along the fitted field: %zu found, moved to whole years (%d x %d x %d rates); saved "
              "field: iso-contour loss %.4f ring spacings, typical ring width %.4f mm\n",
              fitted.peaksMm.size(), rates.heights, rates.azimuths, rates.radii, finalLoss.meanOverFaces,
              project.params.ringWidth);
        }
        saveProject(project, o->out);
        std::printf("project written to %s\n", o->out.c_str());
      }};
}

}  // namespace kerf::cli
