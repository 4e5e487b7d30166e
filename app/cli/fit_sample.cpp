#include "fit_sample.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "detector_option.hpp"
#include "fit/growth_field_fit.hpp"
#include "fit/held_out_faces.hpp"
#include "fit/ring_uncertainty_fit.hpp"
#include "hold_out_option.hpp"
#include "image/gray_image.hpp"
#include "io/image.hpp"
#include "io/sample_folder.hpp"
#include "number_option.hpp"
#include "params/builtin_presets.hpp"
#include "rings/detect_block_rings.hpp"
#include "rings/learned_ring_detector.hpp"
#include "util/error.hpp"

namespace kerf::cli {

namespace fs = std::filesystem;

void addFitSampleOptions(CLI::App* command, FitSampleOptions& o) {
  command
      ->add_option("--principal", o.principal,
                   "Expected pith direction: the block axis x, y or z (default y)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  command->add_flag("--pith-only", o.pithOnly, "Step 1 only: no growth-rate (distortion) fit; uniform rates");
  command->add_flag("--ignore-anatomy", o.ignoreAnatomy,
                    "Fit the pith to the ring contours alone; the fibre direction seen in the photos "
                    "(X_col.png) is still reported");
  command->add_flag("--ignore-traces", o.ignoreTraces,
                    "Fit the ring-localization images' contours only (detected from the photos where there "
                    "are none), not the sample's or project's ring traces");
  cli::addNumber(command, "--anatomy-weight", o.anatomyWeight,
                 "Strength of the anatomical prior on the pith direction (default 1; 0 = report only)", 0.0,
                 100.0);
  cli::addNumber(
      command, "--max-pith-distance", o.maxPithDistance,
      "mm: a pith farther from the block centre is pulled back (default 500, a 1 m log; 0 = no "
      "limit); the rings of a small block barely curve, so the pith may otherwise drift metres away",
      0.0, 10000.0);
  command->add_flag("--ignore-pores", o.ignorePores,
                    "Ring-porous species: do not let the pores choose the pith's side when the ring "
                    "contours cannot, nor where the earlywood starts against the ring lines (both are "
                    "still reported)");
  command->add_option(
      "--species", o.species,
      "Start the wood (colours, pores, rays, ring profile) from this species' preset, e.g. kuri "
      "or nara (kerf-cli params --presets lists them). Default: a sample folder named by its "
      "Mokume code (CN03) gets that species; a project keeps its own wood; 'none' keeps the "
      "defaults");
  cli::addNumber(command, "--knot-mark-accuracy", o.knotMarkAccuracy,
                 "mm: how closely the fitted knots must pass through their marks (every mark; kept in the "
                 "project). Default: each mark's own, 1 mm unless set",
                 0.05, 50.0);
  command->add_flag("--release-knot-marks", o.releaseKnotMarks,
                    "Let the rings place the knots: the knot marks only tell where to start (kept in the "
                    "project)");
  command->add_flag("--ignore-knot-edges", o.ignoreKnotEdges,
                    "Size the knots by the ring contours alone, not by the knot's edge found around each "
                    "mark on its photo (the report gives each outline's size; use this when one is wrong, "
                    "e.g. a resin streak as dark as the knot beside it)");
  addDetectorOption(command, o.detector);
  addHoldOutFaceOption(command, o.holdOut);
  cli::addNumber(command, "--uncertainty", o.uncertaintyRefits,
                 "Also say how sure the fit is inside the block: refit the field N times on resampled ring "
                 "contours (8 is a good choice; each refit takes about as long as the distortion fit) and "
                 "keep the 1-sigma ring position (mm) in the project, for `export-volume --quantity "
                 "ring-uncertainty` and the editor's cut (default 0: not estimated)",
                 0, 64);
}

namespace {

// The document, its photos' sizes checked before any other work (io/sample_folder.hpp). A folder without
// photos is fine: its ring images alone can be fitted.
Project loadSample(const fs::path& sample, bool isProject) {
  if (isProject) {
    Project project = loadProject(sample);
    std::array<fs::path, 6> present = project.facePhotos;  // a project may name photos that are gone
    for (fs::path& photo : present)
      if (!photo.empty() && !fs::exists(photo)) photo.clear();
    validateSampleFolder(present, {}, project.block, true);
    return project;
  }
  const std::array<fs::path, 6> photos = findSampleFacePhotos(sample);
  if (std::any_of(photos.begin(), photos.end(), [](const fs::path& p) { return !p.empty(); }))
    return projectFromSampleFolder(sample);
  Project project;
  project.block = Block(readSampleBlockSize(sample).value_or(glm::vec3(40.0f)));
  return project;
}

const Preset* chosenSpecies(const FitSampleOptions& o, const fs::path& folder, bool isProject) {
  if (!o.species.empty() && o.species != "none") {
    const Preset* species = builtInPreset(o.species);
    if (!species) throw InputError("--species " + o.species + ": no such species preset");
    return species;
  }
  if (!o.species.empty() || isProject) return nullptr;
  fs::path name = fs::absolute(folder).lexically_normal();
  if (name.filename().empty()) name = name.parent_path();  // "CN03/"
  return builtInPresetForSampleName(name.filename().string());
}

}  // namespace

FittedSample fitSample(const FitSampleOptions& o, Context& context) {
  FaceSet heldOut = heldOutFacesFromOption(o.holdOut);  // bad letters fail before any work
  if (o.uncertaintyRefits == 1) throw InputError("--uncertainty needs at least 2 refits");
  if (o.uncertaintyRefits > 0 && o.pithOnly)
    throw InputError("--uncertainty refits the growth rates too: it cannot be used with --pith-only");
  const fs::path sample = o.sample;
  const bool isProject = fs::is_regular_file(sample);
  if (!isProject && !fs::is_directory(sample))
    throw InputError("not a sample folder or project file: " + sample.string());
  const fs::path folder = isProject ? sample.parent_path() : sample;
  FittedSample fitted{loadSample(sample, isProject), {}, 0};
  Project& project = fitted.project;

  // The species: what the texture starts from, before the colours are fitted to the photos.
  if (const Preset* species = chosenSpecies(o, folder, isProject)) {
    project.params = species->applyTo(project.params);
    std::printf("species: %s (%s)%s\n", species->name.c_str(), species->id.c_str(),
                o.species.empty() ? ", from the sample's name; --species to choose another" : "");
  }
  // A project's held-out faces stay held out: the option adds to them, it never brings a photo back.
  heldOut |= project.heldOutFaces;
  try {
    requireFaceLeftToFit(heldOut);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (with " + sample.string() + "'s own held_out_faces " +
                     project.heldOutFaces.letters() + ")");
  }
  project.heldOutFaces = heldOut;

  GrowthFieldFitInput input;
  input.heldOut = heldOut;  // the fit drops whatever of these faces is below (fit/held_out_faces.hpp)
  if (!o.ignoreTraces) input.traces = project.annotations.traces;
  // Knots of the field (Mokume Sec. 5.2.4), held by their marks (issue 19 item 1); what the options say
  // about the marks is kept with them.
  for (KnotMark& mark : project.annotations.knots) {
    if (o.knotMarkAccuracy > 0) mark.accuracyMm = static_cast<float>(o.knotMarkAccuracy);
    if (o.releaseKnotMarks) mark.released = true;
  }
  input.knotMarks = project.annotations.knots;
  // Photos: the anatomical prior (fit/anatomy_prior.hpp), the colours, and the rings where there is no
  // ring image. A held-out face's photo is not even read.
  for (FaceId face : kAllFaces) {
    const fs::path& file = project.facePhotos[faceIndex(face)];
    if (!heldOut.contains(face) && !file.empty() && fs::exists(file))
      fitted.photos[faceIndex(face)] = readImage(file);
  }
  std::array<std::string, 6> sources;  // where each face's rings come from, for the report
  std::array<Image, 6> toDetect;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    if (heldOut.contains(face)) continue;  // not even read: a held-out face's ring image is its photo's
    const fs::path file = findRingLocalizationImage(folder, face);
    if (!file.empty()) {
      input.rings[i] = readRingLocalizationImage(file);
      sources[i] = "from " + file.filename().string();
    } else if (!fitted.photos[i].empty() && input.traces.empty()) {
      // Photos alone: find the rings as the editor's Detect Rings does (Mokume Sec. 5.1).
      std::printf("face %c: no ring map; rings detected from the photo\n", faceLetter(face));
      toDetect[i] = fitted.photos[i];
      sources[i] = "detected from " + project.facePhotos[i].filename().string();
    } else if (input.traces.empty()) {  // a sample traced by hand needs no ring images
      std::fprintf(stderr,
                   "kerf-cli: warning: face %c has no ring-localization image (%c_arl*.png) and no photo; "
                   "skipped\n",
                   faceLetter(face), faceLetter(face));
    }
  }
  if (std::any_of(toDetect.begin(), toDetect.end(), [](const Image& photo) { return !photo.empty(); })) {
    std::fflush(stdout);  // the lines above before the progress on stderr
    const BlockRingDetection detection =
        detectBlockRings(toDetect, project.block, heldOut, context.progress(), ringDetectorNamed(o.detector));
    for (int i = 0; i < 6; ++i)
      if (detection.faces[i]) input.rings[i] = toGray8(detection.faces[i]->arl);
    fitted.facesDetected = detection.faceCount();
  }
  input.photos = fitted.photos;

  GrowthFieldFitOptions options;
  options.principal = o.principal == "x"   ? glm::vec3(1, 0, 0)
                      : o.principal == "z" ? glm::vec3(0, 0, 1)
                                           : glm::vec3(0, 1, 0);
  options.pithOnly = o.pithOnly;
  options.useAnatomy = !o.ignoreAnatomy;
  options.anatomyWeight = o.anatomyWeight;
  options.minContours = kMinFitContours;  // as the editor
  options.minFaces = kMinFitFaces;
  options.plausiblePithDistanceMm = o.maxPithDistance;
  options.pithSideByPores = !o.ignorePores;
  options.earlywoodByPores = !o.ignorePores;
  options.useKnotOutlines = !o.ignoreKnotEdges;
  const GrowthFieldFitResult fit = [&] {
    try {
      return fitGrowthFieldToSample(input, project.block, project.params, options, context.progress());
    } catch (const InputError& e) {  // the fit knows no file names: say which sample failed
      throw InputError(std::string(e.what()) + " (fitting " + sample.string() + ")");
    }
  }();
  for (FaceId face : kAllFaces)
    if (!sources[faceIndex(face)].empty())
      std::printf("face %c: %d contours %s\n", faceLetter(face), fit.report.contoursPerFace[faceIndex(face)],
                  sources[faceIndex(face)].c_str());
  for (const ReportLine& line : formatGrowthFieldFitReport(fit.report)) {
    if (line.severity == Severity::Warning)
      std::fprintf(stderr, "kerf-cli: warning: %s\n", line.text.c_str());
    else
      std::printf("%s\n", line.text.c_str());
  }
  project.ringUncertainty.reset();
  if (o.uncertaintyRefits > 0 && fit.rates) {
    std::printf("uncertainty: refitting the field %d times on resampled contours\n", o.uncertaintyRefits);
    std::fflush(stdout);
    RingUncertaintyOptions u;
    u.replicates = o.uncertaintyRefits;
    const RingUncertainty sure =
        estimateRingUncertainty(input, project.block, fit, options, u, context.progress());
    std::printf(
        "uncertainty: rings within +-%.2f mm (median over the block), +-%.2f mm at the 90th "
        "percentile (1 sigma, %d refits, calibration x%.2f)\n",
        sure.quantile(0.5), sure.quantile(0.9), sure.replicates, sure.calibration);
    project.ringUncertainty = sure;
  }
  project.params = fit.params;
  project.knots = fit.knots;
  project.rates = fit.rates
                      ? *fit.rates
                      : GrowthRates::uniform(project.block,
                                             PithAxis::fromAngles(fit.params.pithOrigin, fit.params.pithTilt,
                                                                  fit.params.pithAzimuth));
  return fitted;
}

}  // namespace kerf::cli
