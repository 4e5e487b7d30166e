// reconstruct: the whole pipeline from a sample's photos to a project, as the editor's one-click
// Reconstruct: the rings (detected from the photos where the sample has no ring images, Mokume Sec. 5.1),
// the growth field (Sec. 5.2), and with --texture the detail of the wood (Sec. 5.3.1); --appearance photo
// makes its surfaces of the photos themselves instead (issue 17, as the editor's Reconstruct with
// Texture > Photo-true Appearance). Each stage says what it does and shows its progress; the project is
// written once, at the end.
#include <cstdio>

#include "command.hpp"
#include "fit_sample.hpp"
#include "io/project.hpp"
#include "texture_step.hpp"
#include "util/resource_usage.hpp"

namespace kerf::cli {

Command addReconstructCommand(CLI::App& app) {
  auto* reconstruct = app.add_subcommand(
      "reconstruct",
      "From photos to a project in one step: detect the rings (where there are no X_arl*.png ring images), "
      "fit the growth field, and with --texture infer the texture detail (docs/fitting.md, docs/texture.md)");
  struct Options {
    FitSampleOptions fit;
    std::string out;
    bool texture = false;
    std::string appearance = "procedural";
  };
  auto o = std::make_shared<Options>();
  reconstruct->fallthrough();  // kerf-cli's own --stats, -q may also follow the subcommand
  reconstruct
      ->add_option(
          "SAMPLE", o->fit.sample,
          "A Mokume-style sample folder (A_col.png .. F_col.png; ring images and traces are used when "
          "present) or a project (.kerf)")
      ->required();
  reconstruct->add_option("--out", o->out, "The project file to write (.kerf)")->required();
  reconstruct->add_flag(
      "--texture", o->texture,
      "Also infer the pores, rays, fibres and colours from the photos (kerf-cli texture with "
      "its defaults). Off by default: it takes tens of seconds (CN03: about 12 s on two idle cores) "
      "on top of the rings and the fit");
  reconstruct
      ->add_option(
          "--appearance", o->appearance,
          "procedural (default): Kerf's procedural wood (its detail inferred with --texture). photo: "
          "every surface made of the sample's own photos, re-grown along the fitted field (seconds; "
          "docs/texture.md), stored in the project; the texture detail is then skipped unless "
          "--texture asks for it too")
      ->check(CLI::IsMember({"procedural", "photo"}));
  addFitSampleOptions(reconstruct, o->fit);
  return {
      reconstruct, [o](Context& context) {
        std::printf("[1/2] rings and growth field of %s\n", o->fit.sample.c_str());
        std::fflush(stdout);  // before the progress on stderr
        const Stopwatch fitClock;
        FittedSample fitted = fitSample(o->fit, context);
        std::printf(
            "[1/2] done in %.1f s (%s)\n", fitClock.seconds(),
            fitted.facesDetected > 0
                ? (std::to_string(fitted.facesDetected) + " faces' rings detected from the photos").c_str()
                : "the sample's own ring images and traces");
        if (o->texture) {
          std::printf(
              "[2/2] texture detail from the photos (pores, rays, fibres, colours; tens of seconds)\n");
          std::fflush(stdout);
          const Stopwatch textureClock;
          const TextureInferenceOptions defaults;  // as kerf-cli texture without options
          inferProjectTexture(fitted.project, fitted.photos, defaults, context);
          std::printf("[2/2] done in %.1f s\n", textureClock.seconds());
        } else if (o->appearance != "photo") {
          std::printf(
              "[2/2] texture detail skipped (it takes tens of seconds): add --texture, or run kerf-cli "
              "texture %s --out %s later\n",
              o->out.c_str(), o->out.c_str());
        }
        if (o->appearance == "photo") {
          std::printf("[2/2] photo-true appearance: the surfaces are made of the photos themselves\n");
          storePhotoAppearance(fitted.project);
        }
        saveProject(fitted.project, o->out);
        std::printf("project written to %s\n", o->out.c_str());
      }};
}

}  // namespace kerf::cli
