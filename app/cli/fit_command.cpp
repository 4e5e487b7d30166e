// fit: infer the growth field from a sample's ring-localization images and/or the user's ring traces
// (Mokume Sec. 5.2: step 1, the pith axis of an undeformed field and the ring width and phase along it;
// step 2, the growth rates R with the grey map M; numbered traces pin the rings to their years as in the
// learned-inference paper, Eq. 5; the pipeline is fitGrowthFieldToSample, fit/growth_field_fit.hpp) and
// write a project. Faces with a photo but no ring image get their rings detected first (fit_sample.hpp).
#include <cstdio>

#include "command.hpp"
#include "fit_sample.hpp"

namespace kerf::cli {

Command addFitCommand(CLI::App& app) {
  auto* fit = app.add_subcommand("fit",
                                 "Fit the growth field (pith axis, growth rates, rings) to a sample's "
                                 "ring-localization images (X_arl*.png; detected from the photos X_col.png "
                                 "where there are none) and ring traces (X_ann.png, or a project's traces)");
  struct Options {
    FitSampleOptions fit;
    std::string out;
  };
  auto o = std::make_shared<Options>();
  fit->add_option(
         "SAMPLE", o->fit.sample,
         "A Mokume-style sample folder (A_col.png .. F_col.png photos, A_arl-unet.png .. ring images, "
         "numbered ring traces A_ann.png ..), or a project (.kerf) whose ring traces are fitted (ring "
         "images beside it are used too)")
      ->required();
  fit->add_option("--out", o->out, "The project file to write (.kerf)")->required();
  addFitSampleOptions(fit, o->fit);
  return {fit, [o](Context& context) {
            const FittedSample fitted = fitSample(o->fit, context);
            saveProject(fitted.project, o->out);
            std::printf("project written to %s\n", o->out.c_str());
          }};
}

}  // namespace kerf::cli
