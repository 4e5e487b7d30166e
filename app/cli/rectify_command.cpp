// rectify: one face image from the user's own photo of a block face: the face's four corners on the
// photo are warped onto a face image of the face's size in mm at --px-per-mm, turned and mirrored into
// the face's image orientation (docs/coordinates.md), and white-balanced (core/io/face_photo_rectify.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "io/atomic_file.hpp"
#include "io/face_photo_rectify.hpp"
#include "io/image.hpp"
#include "number_option.hpp"
#include "util/error.hpp"
#include "util/number_list.hpp"
#include "util/size_limits.hpp"

namespace kerf::cli {
namespace {

std::vector<float> parseNumbers(const std::string& text, std::size_t count, const std::string& option,
                                const std::string& meaning) {
  const std::vector<float> v = parseNumberList(text, option);
  if (v.size() != count)
    throw InputError(option + " takes " + std::to_string(count) + " numbers: " + meaning + " (got " +
                     std::to_string(v.size()) + ")");
  return v;
}

}  // namespace

Command addRectifyCommand(CLI::App& app) {
  auto* rectify = app.add_subcommand(
      "rectify", "Rectify your photo of one block face into a face image (perspective, turn, white balance)");
  struct Options {
    std::string photo, corners, sizeMm, whiteBalance = "none", out;
    float pxPerMm = 0;
    int rotate = 0;
    bool flip = false, stats = false;
  };
  auto o = std::make_shared<Options>();
  rectify->add_option("PHOTO", o->photo, "The photo of the face (any format OpenImageIO reads)")->required();
  rectify
      ->add_option("--corners", o->corners,
                   "x0,y0,x1,y1,x2,y2,x3,y3: the face's corners on the photo in pixels, clockwise from the "
                   "one that becomes the image's top-left (before --rotate/--flip)")
      ->required();
  rectify->add_option("--size-mm", o->sizeMm, "W,H: the face's width and height in mm (in the face image)")
      ->required();
  cli::addNumber(rectify, "--px-per-mm", o->pxPerMm,
                 "Face image resolution (default: what the photo gives along the face's sides, at "
                 "most 20)",
                 0.0f, 200.0f);
  cli::addNumber(rectify, "--rotate", o->rotate, "Quarter turn clockwise after rectifying: 0, 90, 180 or 270",
                 0, 270)
      ->check(CLI::IsMember({0, 90, 180, 270}));
  rectify->add_flag("--flip", o->flip, "Mirror left <-> right after the turn");
  rectify->add_option("--white-balance", o->whiteBalance,
                      "none, auto (from the brightest unclipped pixels: paper, bench, sheen), or x,y,w,h: "
                      "a neutral patch on the photo in pixels");
  rectify->add_option("--out", o->out, "The face image to write (PNG, TIFF, ...)")->required();
  rectify->add_flag("--stats", o->stats,
                    "Also print the photo's resolution and the gains (as kerf-cli --stats)");
  return {
      rectify, [o](Context& context) {
        context.stats = context.stats || o->stats;
        const std::vector<float> c =
            parseNumbers(o->corners, 8, "--corners", "x0,y0,x1,y1,x2,y2,x3,y3 (photo pixels)");
        const std::vector<float> mm = parseNumbers(o->sizeMm, 2, "--size-mm", "W,H (mm)");
        if (mm[0] <= 0 || mm[1] <= 0) throw InputError("--size-mm: the face's sides must be positive");
        if (o->pxPerMm < 0 || o->pxPerMm > 200) throw InputError("--px-per-mm must be in 0 .. 200");

        FacePhotoSetup setup;
        setup.source = o->photo;
        for (int k = 0; k < 4; ++k) setup.corners[k] = {c[2 * k], c[2 * k + 1]};
        setup.rotationDegrees = o->rotate;
        setup.flip = o->flip;
        const Image photo = readImage(o->photo);
        try {
          validateCorners(setup.corners, {photo.width, photo.height});
        } catch (const InputError& e) {
          throw InputError("--corners: " + std::string(e.what()));
        }

        std::string balance = "none";
        if (o->whiteBalance == "auto") {
          setup.whiteBalance = autoWhiteBalance(photo);
          balance = "auto";
        } else if (o->whiteBalance != "none") {
          const std::vector<float> r =
              parseNumbers(o->whiteBalance, 4, "--white-balance", "none, auto or x,y,w,h (photo pixels)");
          setup.whiteBalance = whiteBalanceFromPatch(photo, {r[0], r[1], r[2], r[3]});
          balance = "patch";
        }

        const glm::vec2 faceMm(mm[0], mm[1]);
        const glm::vec2 resolution = photoResolution(setup.corners, faceMm, setup.rotationDegrees);
        float pxPerMm = o->pxPerMm;
        if (pxPerMm == 0) pxPerMm = std::clamp(std::floor(resolution.x * 10.0f) / 10.0f, 1.0f, 20.0f);
        const glm::ivec2 size(pixelsAlong(std::round(double(faceMm.x) * pxPerMm)),
                              pixelsAlong(std::round(double(faceMm.y) * pxPerMm)));
        checkImageSize(size, "the face image", pxPerMm);
        const Image face = rectifyFace(photo, setup, size);
        if (const std::filesystem::path folder = std::filesystem::path(o->out).parent_path(); !folder.empty())
          createOutputFolder(folder);
        writeImage(o->out, face);
        context.samples += static_cast<std::size_t>(size.x) * size.y;
        std::printf("face written to %s (%d x %d px, %.4g px/mm)\n", o->out.c_str(), size.x, size.y, pxPerMm);
        if (context.stats) {
          std::fprintf(stderr,
                       "rectify: photo %d x %d px; the face has %.3g .. %.3g photo px/mm along its sides%s\n",
                       photo.width, photo.height, resolution.x, resolution.y,
                       pxPerMm > resolution.x * 1.05f ? " (the output has more px/mm than the photo)" : "");
          std::fprintf(stderr, "rectify: white balance %s, gains %.4f %.4f %.4f\n", balance.c_str(),
                       setup.whiteBalance.x, setup.whiteBalance.y, setup.whiteBalance.z);
        }
      }};
}

}  // namespace kerf::cli
