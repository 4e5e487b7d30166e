// demo: the bundled demo block.
#include <cstdio>
#include <filesystem>

#include "command.hpp"
#include "demo/demo_block.hpp"
#include "number_option.hpp"

namespace kerf::cli {

Command addDemoCommand(CLI::App& app) {
  auto* demo =
      app.add_subcommand("demo", "Write the bundled demo block: six face photos, true parameters, a project");
  struct Options {
    std::string out;
    DemoOptions demo;
    bool plain = false;
  };
  auto o = std::make_shared<Options>();
  demo->add_option("--out", o->out, "Output folder (created if needed)")->required();
  cli::addNumber(demo, "--size", o->demo.facePixels, "Face image side in pixels (Mokume uses 256)", 8, 8192);
  cli::addNumber(demo, "--seed", o->demo.seed, "Random seed of the demo wood");
  cli::addNumber(demo, "--samples", o->demo.samples, "Supersamples per pixel side", 1, 8);
  demo->add_flag("--no-photo-look", o->plain, "Write the plain rendering, without lighting and noise");
  demo->add_flag("--numbered-traces", o->demo.numberedTraces,
                 "Also write the true rings as numbered ring traces (A_ann.png .. F_ann.png, Mokume format)");
  demo->add_flag(
      "--knot", o->demo.knot,
      "Grow a knot through the block and mark its centres (X_knot.png, Mokume format; docs/fitting.md)");
  return {demo, [o](Context& context) {
            o->demo.photoLook = !o->plain;
            const DemoFiles files = writeDemo(o->out, o->demo, context.progress());
            context.samples = static_cast<std::size_t>(6) * o->demo.facePixels * o->demo.facePixels *
                              o->demo.samples * o->demo.samples;
            std::printf(
                "demo block written to %s\n  photos:  A_col.png .. F_col.png\n  truth:   %s\n  project: %s\n",
                std::filesystem::path(o->out).string().c_str(), files.truth.filename().c_str(),
                files.project.filename().c_str());
          }};
}

}  // namespace kerf::cli
