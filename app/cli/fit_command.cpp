// fit: infer the growth field from a sample's ring-localization images and/or the user's ring traces
// (Mokume Sec. 5.2: step 1, the pith axis of an undeformed field and the ring width and phase along it;
// step 2, the growth rates R with the grey map M; numbered traces pin the rings to their years as in the
// learned-inference paper, Eq. 5; the pipeline is fitGrowthFieldToSample, fit/growth_field_fit.hpp) and
// write a project.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "command.hpp"
#include "fit/growth_field_fit.hpp"
#include "fit/held_out_faces.hpp"
#include "hold_out_option.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "params/builtin_presets.hpp"
#include "util/error.hpp"

namespace kerf::cli {

namespace fs = std::filesystem;

Command addFitCommand(CLI::App& app) {
  auto* fit = app.add_subcommand("fit",
                                 "Fit the growth field (pith axis, growth rates, rings) to a sample's "
                                 "ring-localization images (X_arl*.png) and ring traces (X_ann.png, or a "
                                 "project's traces)");
  struct Options {
    std::string sample, out, principal = "y";
    bool pithOnly = false;
    bool ignoreAnatomy = false;
    bool ignoreTraces = false;
    double anatomyWeight = 1.0;
    std::string species;
    std::vector<std::string> holdOut;
  };
  auto o = std::make_shared<Options>();
  fit->add_option("SAMPLE", o->sample,
                  "A Mokume-style sample folder (A_arl-unet.png .. F_arl-unet.png, numbered ring traces "
                  "A_ann.png ..), or a project (.kerf) whose ring traces are fitted (ring images beside it "
                  "are used too)")
      ->required();
  fit->add_option("--out", o->out, "The project file to write (.kerf)")->required();
  fit->add_option("--principal", o->principal,
                  "Expected pith direction: the block axis x, y or z (default y)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  fit->add_flag("--pith-only", o->pithOnly, "Step 1 only: no growth-rate (distortion) fit; uniform rates");
  fit->add_flag("--ignore-anatomy", o->ignoreAnatomy,
                "Fit the pith to the ring contours alone; the fibre direction seen in the photos (X_col.png) "
                "is still reported");
  fit->add_flag("--ignore-traces", o->ignoreTraces,
                "Fit the ring-localization images' contours only, not the sample's or project's ring traces");
  fit->add_option("--anatomy-weight", o->anatomyWeight,
                  "Strength of the anatomical prior on the pith direction (default 1; 0 = report only)")
      ->check(CLI::Range(0.0, 100.0));
  fit->add_option("--species", o->species,
                  "Start the wood (colours, pores, rays, ring profile) from this species' preset, e.g. kuri or "
                  "nara (kerf-cli params --presets lists them). Default: a sample folder named by its Mokume "
                  "code (CN03) gets that species; a project keeps its own wood; 'none' keeps the defaults");
  addHoldOutFaceOption(fit, o->holdOut);
  return {
      fit, [o](Context& context) {
        FaceSet heldOut = heldOutFacesFromOption(o->holdOut);  // bad letters fail before any work
        const fs::path sample = o->sample;
        const bool isProject = fs::is_regular_file(sample);
        if (!isProject && !fs::is_directory(sample))
          throw InputError("not a sample folder or project file: " + sample.string());
        const fs::path folder = isProject ? sample.parent_path() : sample;
        Project project;  // without photos, the ring images alone are enough to fit
        if (isProject) {
          project = loadProject(sample);
        } else {
          try {
            project = projectFromSampleFolder(folder);
          } catch (const InputError&) {
          }
        }

        // The species: what the texture starts from, before the colours are fitted to the photos.
        const Preset* species = nullptr;
        if (!o->species.empty() && o->species != "none") {
          species = builtInPreset(o->species);
          if (!species) throw InputError("--species " + o->species + ": no such species preset");
        } else if (o->species.empty() && !isProject) {
          fs::path name = fs::absolute(folder).lexically_normal();
          if (name.filename().empty()) name = name.parent_path();  // "CN03/"
          species = builtInPresetForSampleName(name.filename().string());
        }
        if (species) {
          project.params = species->applyTo(project.params);
          std::printf("species: %s (%s)%s\n", species->name.c_str(), species->id.c_str(),
                      o->species.empty() ? ", from the sample's name; --species to choose another" : "");
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
        if (!o->ignoreTraces) input.traces = project.annotations.traces;
        input.knotMarks = project.annotations.knots;  // knots of the field (Mokume Sec. 5.2.4)
        std::array<std::string, 6> files;
        for (FaceId face : kAllFaces) {
          if (heldOut.contains(face)) continue;  // not even read: a held-out face's ring image is its photo's
          const fs::path file = findRingLocalizationImage(folder, face);
          if (file.empty()) {
            // A sample traced by hand needs no ring images; otherwise say which face is skipped.
            if (input.traces.empty())
              std::fprintf(stderr,
                           "kerf-cli: warning: face %c has no ring-localization image (%c_arl*.png); "
                           "skipped\n",
                           faceLetter(face), faceLetter(face));
            continue;
          }
          input.rings[faceIndex(face)] = readRingLocalizationImage(file);
          files[faceIndex(face)] = file.filename().string();
        }
        // Photos for the anatomical prior (fit/anatomy_prior.hpp).
        for (FaceId face : kAllFaces) {
          if (heldOut.contains(face)) continue;
          const fs::path file = isProject ? project.facePhotos[faceIndex(face)]
                                          : folder / (std::string(1, faceLetter(face)) + "_col.png");
          if (!file.empty() && fs::exists(file)) input.photos[faceIndex(face)] = readImage(file);
        }
        GrowthFieldFitOptions options;
        options.principal = o->principal == "x"   ? glm::vec3(1, 0, 0)
                            : o->principal == "z" ? glm::vec3(0, 0, 1)
                                                  : glm::vec3(0, 1, 0);
        options.pithOnly = o->pithOnly;
        options.useAnatomy = !o->ignoreAnatomy;
        options.anatomyWeight = o->anatomyWeight;
        const GrowthFieldFitResult fit = [&] {
          try {
            return fitGrowthFieldToSample(input, project.block, project.params, options, context.progress());
          } catch (const InputError& e) {  // the fit knows no file names: say which sample failed
            throw InputError(std::string(e.what()) + " (fitting " + sample.string() + ")");
          }
        }();
        for (FaceId face : kAllFaces)
          if (!files[faceIndex(face)].empty())
            std::printf("face %c: %d contours from %s\n", faceLetter(face),
                        fit.report.contoursPerFace[faceIndex(face)], files[faceIndex(face)].c_str());
        for (const std::string& line : formatGrowthFieldFitReport(fit.report)) {
          if (line.rfind("warning: ", 0) == 0)
            std::fprintf(stderr, "kerf-cli: %s\n", line.c_str());
          else
            std::printf("%s\n", line.c_str());
        }
        project.params = fit.params;
        project.knots = fit.knots;
        project.rates =
            fit.rates ? *fit.rates
                      : GrowthRates::uniform(project.block,
                                             PithAxis::fromAngles(fit.params.pithOrigin, fit.params.pithTilt,
                                                                  fit.params.pithAzimuth));
        saveProject(project, o->out);
        std::printf("project written to %s\n", o->out.c_str());
      }};
}

}  // namespace kerf::cli
