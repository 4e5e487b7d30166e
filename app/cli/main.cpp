// kerf-cli: Kerf's core, headless, for batch work and tests. Every subcommand prints a clear message
// and exits non-zero on bad input; --stats prints timing, throughput and peak memory.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "demo/demo_block.hpp"
#include "geometry/cut_plane.hpp"
#include "io/project.hpp"
#include "render/renderers.hpp"
#include "render/unfolded_cross.hpp"
#include "render/volume_export.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/resource_usage.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

struct Stats {
  bool enabled = false;
  Stopwatch clock;
  std::size_t samples = 0;  // model evaluations (pixels/voxels x supersamples)
  void print(const std::string& command) const {
    if (!enabled) return;
    const double s = clock.seconds();
    std::fprintf(
        stderr,
        "stats: command=%s wall=%.3f s threads=%d samples=%zu throughput=%.3g samples/s peak_rss=%.1f MiB\n",
        command.c_str(), s, workerThreads(), samples, s > 0 ? samples / s : 0.0,
        peakResidentBytes() / (1024.0 * 1024.0));
  }
};

glm::vec3 parseTriple(const std::string& text, const char* what) {
  std::istringstream in(text);
  float v[6];
  char comma;
  int count = 0;
  while (count < 6 && in >> v[count]) {
    ++count;
    if (!(in >> comma)) break;
    if (comma != ',') throw InputError(std::string(what) + ": expected numbers separated by commas");
  }
  if (count != 3) throw InputError(std::string(what) + ": expected 3 numbers x,y,z");
  return {v[0], v[1], v[2]};
}

CutPlane parsePlane(const std::string& text) {
  std::istringstream in(text);
  std::vector<float> v;
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stof(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError("--plane: \"" + item + "\" is not a number");
    }
  }
  if (v.size() != 6)
    throw InputError("--plane takes 6 numbers: px,py,pz,nx,ny,nz (a point and a normal, block mm)");
  return CutPlane({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
}

Progress consoleProgress(bool quiet) {
  if (quiet) return {};
  auto last = std::make_shared<int>(-1);
  return {[last](double f) {
            const int percent = static_cast<int>(f * 100.0);
            if (percent / 10 != *last / 10) {
              *last = percent;
              std::fprintf(stderr, "\r%3d%%", percent);
              if (percent >= 100) std::fprintf(stderr, "\n");
            }
          },
          {}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "kerf-cli: Kerf's wood model, headless (demo, render-faces, render-cut, export-volume, params)"};
  app.require_subcommand(1);
  Stats stats;
  int threads = 0;
  bool quiet = false;
  app.add_flag("--stats", stats.enabled, "Print wall time, threads, throughput and peak memory on stderr");
  app.add_option("--threads", threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 256));
  app.add_flag("-q,--quiet", quiet, "No progress output");

  // demo
  auto* demo =
      app.add_subcommand("demo", "Write the bundled demo block: six face photos, true parameters, a project");
  std::string demoOut;
  DemoOptions demoOptions;
  demo->add_option("--out", demoOut, "Output folder (created if needed)")->required();
  demo->add_option("--size", demoOptions.facePixels, "Face image side in pixels (Mokume uses 256)")
      ->check(CLI::Range(8, 8192));
  demo->add_option("--seed", demoOptions.seed, "Random seed of the demo wood");
  demo->add_option("--samples", demoOptions.samples, "Supersamples per pixel side")->check(CLI::Range(1, 8));
  bool plainFaces = false;
  demo->add_flag("--no-photo-look", plainFaces, "Write the plain rendering, without lighting and noise");

  // render-faces
  auto* faces = app.add_subcommand("render-faces", "Render the model's six faces A.png..F.png");
  std::string facesDoc, facesOut;
  float facesPxPerMm = 6.4f;
  int facesSamples = 2;
  faces->add_option("PROJECT", facesDoc, "A .kerf project or a Mokume-style sample folder")->required();
  faces->add_option("--out", facesOut, "Output folder (created if needed)")->required();
  faces->add_option("--px-per-mm", facesPxPerMm, "Resolution (6.4 = Mokume's 256 px per 40 mm)")
      ->check(CLI::Range(0.01f, 400.0f));
  faces->add_option("--samples", facesSamples, "Supersamples per pixel side")->check(CLI::Range(1, 8));
  bool facesCross = false;
  faces->add_flag("--unfolded", facesCross, "Also write unfolded.png: the faces in the Mokume cross layout");

  // render-cut
  auto* cut =
      app.add_subcommand("render-cut", "Render the cut surface of a plane through the block (RGBA PNG)");
  std::string cutDoc, cutPlaneText, cutOut;
  float cutPxPerMm = 10.0f;
  int cutSamples = 2;
  cut->add_option("PROJECT", cutDoc, "A .kerf project or a Mokume-style sample folder")->required();
  cut->add_option("--plane", cutPlaneText, "px,py,pz,nx,ny,nz: a point on the plane and its normal, block mm")
      ->required();
  cut->add_option("--px-per-mm", cutPxPerMm, "Resolution of the cut image")->check(CLI::Range(0.01f, 400.0f));
  cut->add_option("--samples", cutSamples, "Supersamples per pixel side")->check(CLI::Range(1, 8));
  cut->add_option("--out", cutOut, "Output image (.png, .tif, ...)")->required();

  // export-volume
  auto* volume = app.add_subcommand("export-volume", "Write the growth field or the colour as a NRRD volume");
  std::string volumeDoc, volumeQuantity = "growth", volumeOut;
  int volumeRes = 128;
  volume->add_option("PROJECT", volumeDoc, "A .kerf project or a Mokume-style sample folder")->required();
  volume->add_option("--quantity", volumeQuantity, "growth (float years) or color (uint8 RGB)")
      ->check(CLI::IsMember({"growth", "color"}));
  volume->add_option("--res", volumeRes, "Samples along the block's longest side")
      ->check(CLI::Range(1, 4096));
  volume->add_option("--out", volumeOut, "Output .nrrd file")->required();

  // params
  auto* params = app.add_subcommand("params", "Print the parameter schema as JSON");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  setWorkerThreads(threads);

  try {
    if (*demo) {
      demoOptions.photoLook = !plainFaces;
      const DemoFiles files = writeDemo(demoOut, demoOptions, consoleProgress(quiet));
      stats.samples = static_cast<std::size_t>(6) * demoOptions.facePixels * demoOptions.facePixels *
                      demoOptions.samples * demoOptions.samples;
      std::printf(
          "demo block written to %s\n  photos:  A_col.png .. F_col.png\n  truth:   %s\n  project: %s\n",
          fs::path(demoOut).string().c_str(), files.truth.filename().c_str(),
          files.project.filename().c_str());
      stats.print("demo");
    } else if (*faces) {
      const Project project = loadDocument(facesDoc);
      const WoodModel model(project);
      fs::create_directories(facesOut);
      const auto images = renderFaces(model, facesPxPerMm, facesSamples, consoleProgress(quiet));
      for (FaceId face : kAllFaces) {
        const Image& image = images[faceIndex(face)];
        writeImage(fs::path(facesOut) / (std::string(1, faceLetter(face)) + ".png"), image);
        stats.samples += static_cast<std::size_t>(image.width) * image.height * facesSamples * facesSamples;
      }
      if (facesCross) writeImage(fs::path(facesOut) / "unfolded.png", unfoldedCross(images, model.block()));
      std::printf("faces written to %s (A.png .. F.png%s)\n", facesOut.c_str(),
                  facesCross ? ", unfolded.png" : "");
      stats.print("render-faces");
    } else if (*cut) {
      const CutPlane plane = parsePlane(cutPlaneText);
      const Project project = loadDocument(cutDoc);
      const WoodModel model(project);
      const Image image = renderCut(model, plane, cutPxPerMm, cutSamples, consoleProgress(quiet));
      writeImage(cutOut, image);
      stats.samples = static_cast<std::size_t>(image.width) * image.height * cutSamples * cutSamples;
      std::printf("cut written to %s (%dx%d px, %.3g px/mm)\n", cutOut.c_str(), image.width, image.height,
                  cutPxPerMm);
      stats.print("render-cut");
    } else if (*volume) {
      const Project project = loadDocument(volumeDoc);
      const WoodModel model(project);
      const VolumeExportResult result = exportVolume(model, volumeQuantityFromName(volumeQuantity), volumeRes,
                                                     volumeOut, consoleProgress(quiet));
      stats.samples = result.samples;
      std::printf("volume written to %s (%d x %d x %d samples, %.4g mm spacing, %.1f MiB)\n",
                  volumeOut.c_str(), result.size.x, result.size.y, result.size.z, result.spacingMm.x,
                  result.bytes / 1048576.0);
      stats.print("export-volume");
    } else if (*params) {
      nlohmann::ordered_json out = nlohmann::ordered_json::array();
      for (const ParamSpec& spec : parameterSchema()) {
        nlohmann::ordered_json def =
            spec.components() == 1 ? nlohmann::ordered_json(spec.defaultValue[0])
                                   : nlohmann::ordered_json::array(
                                         {spec.defaultValue[0], spec.defaultValue[1], spec.defaultValue[2]});
        out.push_back({{"id", spec.id},
                       {"group", spec.group},
                       {"label", spec.label},
                       {"unit", spec.unit},
                       {"kind", paramKindName(spec.kind)},
                       {"default", def},
                       {"soft_range", {spec.softMin, spec.softMax}},
                       {"hard_range", {spec.hardMin, spec.hardMax}},
                       {"fittable", spec.fittable},
                       {"glsl_uniform", "u_" + std::string(spec.name)},
                       {"tooltip", spec.tooltip}});
      }
      std::cout << out.dump(2) << "\n";
      stats.print("params");
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "kerf-cli: error: %s\n", e.what());
    return 2;
  } catch (const Cancelled&) {
    std::fprintf(stderr, "kerf-cli: cancelled\n");
    return 130;
  } catch (const fs::filesystem_error& e) {
    std::fprintf(stderr, "kerf-cli: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
