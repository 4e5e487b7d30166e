#pragma once
// The growth-field fit of a sample folder or project, as `kerf-cli fit` and `kerf-cli reconstruct` run it:
// load (the photos' sizes checked first), the species preset, the ring-localization images, Kerf's own
// ring detection on faces that have a photo but no ring image (as the editor's Detect Rings does), then
// fitGrowthFieldToSample (fit/growth_field_fit.hpp) with its report on stdout.
#include <CLI/CLI.hpp>
#include <array>
#include <string>
#include <vector>

#include "command.hpp"
#include "fit/growth_field_fit.hpp"
#include "io/image.hpp"
#include "io/project.hpp"

namespace kerf::cli {

struct FitSampleOptions {
  std::string sample;  // a Mokume-style sample folder or a .kerf project
  std::string principal = "y";
  bool pithOnly = false;
  bool ignoreAnatomy = false;
  bool ignoreTraces = false;
  double anatomyWeight = 1.0;
  double maxPithDistance = GrowthFieldFitOptions{}.plausiblePithDistanceMm;
  bool ignorePores = false;  // !GrowthFieldFitOptions::pithSideByPores
  std::string species;
  std::vector<std::string> holdOut;
  int uncertaintyRefits = 0;  // > 0: how sure the fit is (fit/ring_uncertainty_fit.hpp), kept in the project
  double knotMarkAccuracy = 0;    // > 0: every knot mark's accuracy (mm), kept in the project
  bool releaseKnotMarks = false;  // knot marks only seed their knots (kept in the project)
  bool ignoreKnotEdges = false;   // !GrowthFieldFitOptions::useKnotOutlines
  std::string detector =
      "classical";  // rings/learned_ring_detector.hpp ringDetectorNamed, for photos without ring maps
};

// The options of the fit besides SAMPLE and --out, on `fit` and `reconstruct` alike.
void addFitSampleOptions(CLI::App* command, FitSampleOptions& options);

struct FittedSample {
  Project project;              // the fitted field in it, held-out faces recorded
  std::array<Image, 6> photos;  // the photos the fit read (none of the held-out faces)
  int facesDetected = 0;        // faces whose rings Kerf detected from the photo
};

// Throws InputError (naming the sample) on bad input or too few rings, Cancelled on request.
FittedSample fitSample(const FitSampleOptions& options, Context& context);

}  // namespace kerf::cli
