// detect: automatic ring localization on the face photos of a sample folder or project
// (Mokume Sec. 5.1): DIR/A_arl.png .. F_arl.png and DIR/contours.json (docs/rings.md).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command.hpp"
#include "detector_option.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "rings/detect_block_rings.hpp"
#include "rings/learned_ring_detector.hpp"
#include "util/error.hpp"

namespace fs = std::filesystem;

namespace kerf::cli {

Command addDetectCommand(CLI::App& app) {
  auto* detect = app.add_subcommand(
      "detect", "Find the annual rings on the face photos: A_arl.png..F_arl.png and contours.json");
  struct Options {
    std::string document, out;
    bool allowMissing = false;
    std::string detector = "classical";
  };
  auto o = std::make_shared<Options>();
  detect->add_option("SAMPLE", o->document, "A Mokume-style sample folder (A_col.png ..) or a .kerf project")
      ->required();
  detect->add_option("--out", o->out, "Output folder (created if needed)")->required();
  detect->add_flag("--allow-missing", o->allowMissing, "Skip faces without a photo instead of failing");
  addDetectorOption(detect, o->detector);
  return {
      detect, [o](Context& context) {
        const Project project = loadDocument(o->document);
        std::vector<FaceId> faces;
        std::string missing;
        for (FaceId face : kAllFaces) {
          if (project.heldOutFaces.contains(face)) continue;  // leave-one-face-out: no rings from its photo
          if (!project.facePhotos[faceIndex(face)].empty())
            faces.push_back(face);
          else
            missing += std::string(missing.empty() ? "" : ", ") + faceLetter(face);
        }
        if (!missing.empty() && !o->allowMissing)
          throw InputError(o->document + " has no photo for face " + missing +
                           " (expected <face>_col.png; --allow-missing skips those faces)");
        if (!project.heldOutFaces.empty())
          std::printf("held out (the project's held_out_faces): %s, not detected\n",
                      project.heldOutFaces.letters().c_str());
        // Sizes from the headers first: a photo too big to detect on is refused before any is decoded.
        for (FaceId face : faces) {
          const fs::path& photo = project.facePhotos[faceIndex(face)];
          const glm::ivec2 size = readImageSize(photo);
          checkRingDetectionSize(size.x, size.y,
                                 "face " + std::string(1, faceLetter(face)) + " photo " + photo.string());
        }
        std::array<Image, 6> photos;
        for (FaceId face : faces) photos[faceIndex(face)] = readImage(project.facePhotos[faceIndex(face)]);
        createOutputFolder(o->out);
        // All outputs go to a hidden staging folder first and are moved into --out together at the end:
        // a full disk or a kill half-way must not leave a mix of new and old X_arl.png that a later fit
        // would read as one detection (issue 21).
        const fs::path staging = temporaryFileFor(fs::path(o->out) / "detect");
        createOutputFolder(staging);
        struct RemoveStaging {
          fs::path path;
          ~RemoveStaging() {
            std::error_code ignored;
            fs::remove_all(path, ignored);
          }
        } removeStaging{staging};
        std::vector<std::string> written;
        const RingDetector& detector = ringDetectorNamed(o->detector);
        const BlockRingDetection detection =
            detectBlockRings(photos, project.block, project.heldOutFaces, context.progress(), detector);
        nlohmann::json facesJson = nlohmann::json::object();
        for (FaceId face : faces) {
          const DetectedFaceRings& rings = *detection.faces[faceIndex(face)];
          const std::string letter(1, faceLetter(face));
          const fs::path photoPath = project.facePhotos[faceIndex(face)];
          const Image& photo = photos[faceIndex(face)];
          if (!rings.squarePixels()) {
            const FaceFrame frame = project.block.face(face);
            std::fprintf(stderr,
                         "kerf-cli: warning: face %s photo %s is %dx%d px but the face is %.4g x %.4g mm; "
                         "the pixels are not square\n",
                         letter.c_str(), photoPath.filename().c_str(), photo.width, photo.height,
                         frame.widthMm, frame.heightMm);
          }
          writeImage(staging / (letter + "_arl.png"), rings.arl);
          written.push_back(letter + "_arl.png");
          nlohmann::json list = nlohmann::json::array();
          for (const FaceContour& c : rings.contours) {
            nlohmann::json points = nlohmann::json::array();
            for (const glm::ivec2& p : c.pixels) points.push_back({p.x, p.y});
            list.push_back(std::move(points));
          }
          facesJson[letter] = {{"photo", photoPath.filename().string()},
                               {"arl", letter + "_arl.png"},
                               {"width", rings.arl.width},
                               {"height", rings.arl.height},
                               {"px_per_mm", rings.meanPxPerMm()},
                               {"contours", std::move(list)}};
          context.samples += static_cast<std::size_t>(photo.width) * photo.height;
        }
        const nlohmann::json document = {
            {"format", "kerf-ring-contours"},
            {"version", 1},
            {"detector", detector.name()},
            {"threshold", 200},
            {"pixel_convention",
             "[x, y] = column, row of the ARL image; the pixel's centre is at Kerf image coordinates "
             "(x + 0.5, y + 0.5)"},
            {"faces", std::move(facesJson)}};
        writeTextAtomically(staging / "contours.json", document.dump() + "\n");
        written.push_back("contours.json");
        // contours.json last: a reader that finds it finds the images of the same run.
        for (const std::string& name : written) fs::rename(staging / name, fs::path(o->out) / name);
        std::printf("rings written to %s (%zu faces: <face>_arl.png, contours.json); contours per face: %s\n",
                    o->out.c_str(), faces.size(), detection.countsText().c_str());
      }};
}

}  // namespace kerf::cli
