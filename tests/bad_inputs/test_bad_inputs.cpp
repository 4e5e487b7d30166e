// The catalogue of bad inputs (issue 8; the table in docs/reliability.md): each case makes one broken
// file or folder, opens it the way Kerf's core does, and runs kerf-cli on it. The outcome is exact: an
// InputError whose message names the file and the problem (a loader that throws leaves the caller's
// document as it was), and kerf-cli exits with 2 and prints "kerf-cli: error: ..." naming the file,
// without writing any output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/geometric.hpp>
#include <regex>

#include "bad_input_files.hpp"
#include "io/image.hpp"
#include "io/log_data_import.hpp"
#include "io/project.hpp"
#include "mesh/mesh_loader.hpp"
#include "run_cli.hpp"
#include "util/error.hpp"

using namespace kerf;
using namespace kerf::bad;

namespace {

struct BadInput {
  const char* name;
  // Writes the bad input into `dir` and returns the file (or folder) at fault.
  std::function<fs::path(const fs::path& dir)> make;
  // How the core opens it; nullptr where only kerf-cli's own check applies.
  std::function<void(const fs::path&)> open;
  // What the message must say (a regex searched in the text after the file's name).
  const char* problem;
  // kerf-cli arguments: {file} the input, {dir} its folder, {out} a fresh output folder. nullptr: none.
  const char* cli;
};

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

// ---- makers ---------------------------------------------------------------------------------------

fs::path sampleWith(const fs::path& dir, const std::function<fs::path(const fs::path&)>& breakIt) {
  writeSample(dir);
  return breakIt(dir);
}

fs::path projectFile(const fs::path& dir, const std::string& json) {
  writeText(dir / "bad.kerf", json);
  return dir / "bad.kerf";
}

fs::path projectWith(const fs::path& dir, const std::string& members) {
  return projectFile(dir, R"({"format": "kerf-project", "version": 1, )" + members + "}");
}

const std::string kGoodLog =
    R"({"format": "kerf-log", "version": 1, "name": "t", "stem": {"height_step_mm": 100, "azimuths": 3,
        "pith_mm": [[0, 0], [0, 0], [0, 0]], "radii_mm": [50, 50, 50, 50, 50, 50, 50, 50, 50]},
        "knots": [{"distance_step_mm": 4, "height_mm": [100, 104], "azimuth_rad": [0, 0.1],
                   "death_distance_mm": null, "end_distance_mm": null}]})";

fs::path logFile(const fs::path& dir, const std::string& json) {
  writeText(dir / "bad.kerflog", json);
  return dir / "bad.kerflog";
}

// A ring-localization image: bright rings every `spacing` px around `centre` (in pixels, may be off the
// image).
Image ringImage(int px, glm::vec2 centre, float spacing) {
  Image image(px, px, 1);
  for (int y = 0; y < px; ++y)
    for (int x = 0; x < px; ++x) {
      const float r = glm::length(glm::vec2(x + 0.5f, y + 0.5f) - centre);
      image.pixel(x, y)[0] = std::pow(0.5f * (std::cos(6.2831853f * r / spacing) + 1.0f), 10.0f);
    }
  return image;
}

void openDocument(const fs::path& p) {
  (void)loadDocument(p);
}
// The sample folder the file at fault lies in, opened as a document.
void openSample(const fs::path& p) {
  (void)loadDocument(p.parent_path());
}
void openImage(const fs::path& p) {
  (void)readImage(p);
}
void openLog(const fs::path& p) {
  (void)loadLog(p);
}

const char* const kRenderFaces = "render-faces {file} --out {out} --px-per-mm 0.5 --samples 1";
const char* const kDetect = "detect {dir} --out {out}";
const char* const kRectify =
    "rectify {file} --corners 0,0,15,0,15,15,0,15 --size-mm 16,16 --out {out}/face.png";
const char* const kExportPart = "export {dir}/../demo.kerf --mesh {file} --out {dir}/part.obj";

// Two unit cubes touching along the edge x = y = 1 (as OBJ, each with its own corners): four triangles
// meet on that edge.
const char* const kTwoCubesObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
    "v 1 1 0\nv 2 1 0\nv 1 2 0\nv 2 2 0\nv 1 1 1\nv 2 1 1\nv 1 2 1\nv 2 2 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
    "f 9 11 12 10\nf 13 14 16 15\nf 9 10 14 13\nf 11 15 16 12\nf 9 13 15 11\nf 10 12 16 14\n";

const char* const kRenderBoard = "render-board {file} --out {out}/board.png --res 64";

const BadInput kCatalogue[] = {
    // --- photos ---
    {"PhotoTruncatedPng",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         truncateFile(s / "A_col.png", 0.5);
         return s / "A_col.png";
       });
     },
     openImage, "cannot decode image .*A_col.png: the PNG file is truncated", kDetect},
    {"PhotoCorruptPng",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         corruptAfter(s / "B_col.png", 8);
         return s / "B_col.png";
       });
     },
     openSample, "cannot read image .*B_col.png", kDetect},
    {"PhotoTruncatedTiff",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         fs::remove(s / "C_col.png");
         writePhoto(s / "C_col.tif", 16, 16);
         truncateFile(s / "C_col.tif", 0.3);
         return s / "C_col.tif";
       });
     },
     openImage, "cannot decode image|cannot read image", kDetect},
    {"PhotoCorruptTiff",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         fs::remove(s / "D_col.png");
         writePhoto(s / "D_col.tif", 16, 16);
         corruptAfter(s / "D_col.tif", 4);
         return s / "D_col.tif";
       });
     },
     openSample, "cannot read image .*D_col.tif", kDetect},
    {"PhotoTruncatedExr",
     [](const fs::path& d) {
       writePhoto(d / "face.exr", 16, 16);
       truncateFile(d / "face.exr", 0.5);
       return d / "face.exr";
     },
     openImage, "cannot decode image|cannot read image", kRectify},
    {"PhotoCorruptExr",
     [](const fs::path& d) {
       writePhoto(d / "face.exr", 16, 16);
       corruptAfter(d / "face.exr", 4);
       return d / "face.exr";
     },
     openImage, "cannot read image|cannot decode image", kRectify},
    {"PhotoEmptyFile",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         writeText(s / "E_col.png", "");
         return s / "E_col.png";
       });
     },
     openSample, "cannot read image .*E_col.png", kDetect},
    {"PhotoClaims20000x20000Pixels",
     [](const fs::path& d) {
       writePngClaiming(d / "huge.png", 20000, 20000);
       return d / "huge.png";
     },
     openImage, "is 20000 x 20000 pixels; Kerf reads images up to 120 megapixels", kRectify},
    {"PhotosOfDifferentSizes",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         writePhoto(s / "B_col.png", 16, 24);
         return s / "B_col.png";
       });
     },
     openSample, "B_col.png is 16 x 24 px", kDetect},
    {"PhotosOfOnePixel",  // issue 21: refused without naming the face or the file
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         for (const char* face : {"A", "B", "C", "D", "E", "F"})
           writePhoto(s / (std::string(face) + "_col.png"), 1, 1);
         return s / "A_col.png";
       });
     },
     nullptr, "is 1 x 1 px; ring detection needs at least 4 x 4 px", kDetect},
    // --- sample folders ---
    {"SampleFolderEmpty", [](const fs::path& d) { return d; }, openDocument,
     "holds no face photos \\(expected A_col.png .. F_col.png\\)", kDetect},
    {"SampleFolderMissingFaces",
     [](const fs::path& d) {
       writePhoto(d / "A_col.png", 16, 16);
       return d;
     },
     nullptr, "has no photo for face B, C, D, E, F", kDetect},
    {"BlockJsonMalformed",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         writeText(s / "block.json", "{\"size_mm\": [40, 40,");
         return s / "block.json";
       });
     },
     openSample, "is not valid JSON", kDetect},
    {"BlockJsonNegativeSize",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         writeText(s / "block.json", R"({"size_mm": [40, -40, 40]})");
         return s / "block.json";
       });
     },
     openSample, "\"size_mm\" must be three positive lengths in mm", kDetect},
    // --- Mokume annotation images ---
    {"RingImageOfTheWrongSize",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         writePhoto(s / "A_ann.png", 10, 30, 1);
         return s / "A_ann.png";
       });
     },
     openSample, "A_ann.png is 10 x 30 px", kDetect},
    {"RingImageWithoutBackground",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         Image dark(16, 16, 1);  // every pixel "year 0": an inverted or unrelated image
         writeImage(s / "B_ann.png", dark);
         return s / "B_ann.png";
       });
     },
     openSample, "B_ann.png has no background", kDetect},
    {"RingImageCorrupt",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         writePhoto(s / "C_ann.png", 16, 16, 1);
         corruptAfter(s / "C_ann.png", 8);
         return s / "C_ann.png";
       });
     },
     openSample, "cannot read image .*C_ann.png", kDetect},
    {"KnotImageOfTheWrongSize",
     [](const fs::path& d) {
       return sampleWith(d, [](const fs::path& s) {
         writePhoto(s / "D_knot.png", 40, 5, 1);
         return s / "D_knot.png";
       });
     },
     openSample, "D_knot.png is 40 x 5 px", kDetect},
    // --- project files ---
    {"ProjectNotJson", [](const fs::path& d) { return projectFile(d, "this is no project"); }, openDocument,
     "is not valid JSON \\(byte 2\\)", kRenderFaces},
    {"ProjectTruncated",
     [](const fs::path& d) {
       return projectFile(d, R"({"format": "kerf-project", "version": 1, "block": {"size)");
     },
     openDocument, "is not valid JSON \\(byte 57\\): .*missing closing quote", kRenderFaces},
    {"ProjectEmptyFile", [](const fs::path& d) { return projectFile(d, ""); }, openDocument,
     "is not valid JSON \\(byte 1\\)", kRenderFaces},
    {"ProjectIsAnImage",
     [](const fs::path& d) {
       writePhoto(d / "photo.png", 8, 8);  // PNG bytes under a .kerf name
       fs::rename(d / "photo.png", d / "bad.kerf");
       return d / "bad.kerf";
     },
     openDocument, "is not valid JSON", kRenderFaces},
    {"ProjectFormatOfTheWrongType",
     [](const fs::path& d) { return projectFile(d, R"({"format": 5, "version": 1})"); }, openDocument,
     "not a Kerf project", kRenderFaces},
    {"ProjectParametersOfTheWrongType",
     [](const fs::path& d) { return projectWith(d, R"("parameters": [1, 2])"); }, openDocument,
     "\"parameters\" must be an object", kRenderFaces},
    {"ProjectBlockSizeOfTheWrongType",
     [](const fs::path& d) { return projectWith(d, R"("block": {"size_mm": "large"})"); }, openDocument,
     "block.size_mm must be a list of 3 numbers", kRenderFaces},
    {"ProjectCutPlaneFlagOfTheWrongType",
     [](const fs::path& d) { return projectWith(d, R"("view": {"cut_plane": {"enabled": "yes"}})"); },
     openDocument, "view.cut_plane.enabled must be true or false", kRenderFaces},
    {"ProjectFromAFutureVersion",
     [](const fs::path& d) { return projectFile(d, R"({"format": "kerf-project", "version": 7})"); },
     openDocument, "written by a newer Kerf \\(format version 7\\)", kRenderFaces},
    {"ProjectNaNParameter",  // JSON has no NaN; writers that have one put null
     [](const fs::path& d) { return projectWith(d, R"("parameters": {"growth.ring_width": null})"); },
     openDocument, "parameter growth.ring_width must be a number, got null", kRenderFaces},
    {"ProjectInfiniteParameter",
     [](const fs::path& d) { return projectWith(d, R"("parameters": {"growth.ring_width": 1e999})"); },
     openDocument, "is not valid JSON: number overflow parsing '1e999'", kRenderFaces},
    {"ProjectParameterOutOfRange",
     [](const fs::path& d) { return projectWith(d, R"("parameters": {"growth.ring_width": -3})"); },
     openDocument, "growth.ring_width = -3 is outside its allowed range", kRenderFaces},
    {"ProjectUnknownParameter",
     [](const fs::path& d) { return projectWith(d, R"("parameters": {"growth.ring_wdith": 3})"); },
     openDocument, "unknown parameter \"growth.ring_wdith\"", kRenderFaces},
    {"ProjectGrowthRatesOfTheWrongSize",
     [](const fs::path& d) {
       return projectWith(d, R"("growth_rates": {"heights": 2, "azimuths": 2, "radii": 2,
           "height_range_mm": [0, 1], "radius_range_mm": [0, 5], "rates": [1, 1]})");
     },
     openDocument, "growth-rate grid holds 2 values, expected 8", kRenderFaces},
    // --- logs ---
    {"LogFromAFutureVersion",
     [](const fs::path& d) { return logFile(d, replaceAll(kGoodLog, "\"version\": 1", "\"version\": 3")); },
     openLog, "written by a newer Kerf \\(log format version 3\\)", kRenderBoard},
    {"LogTruncated", [](const fs::path& d) { return logFile(d, kGoodLog.substr(0, kGoodLog.size() / 2)); },
     openLog, "is not valid JSON", kRenderBoard},
    {"LogNameOfTheWrongType",
     [](const fs::path& d) { return logFile(d, replaceAll(kGoodLog, "\"name\": \"t\"", "\"name\": 5")); },
     openLog, "\"name\" must be a string", kRenderBoard},
    {"LogAzimuthCountHuge",
     [](const fs::path& d) {
       return logFile(d, replaceAll(kGoodLog, "\"azimuths\": 3", "\"azimuths\": 1e30"));
     },
     openLog, "stem.azimuths must be a whole number from 3 to", kRenderBoard},
    {"LogWithoutStem",
     [](const fs::path& d) { return logFile(d, R"({"format": "kerf-log", "version": 1})"); }, openLog,
     "has no \"stem\" object", kRenderBoard},
    {"LogKnotOutsideTheStem",
     [](const fs::path& d) { return logFile(d, replaceAll(kGoodLog, "[100, 104]", "[5000, 5004]")); },
     openLog, "knot 0 starts at height 5000.* mm, outside the stem \\(0 to 200.* mm\\)", kRenderBoard},
    {"LogStemRadiusImplausible",  // issue 21: one CT radius of 1e30 changed the whole board
     [](const fs::path& d) {
       return logFile(d, replaceAll(kGoodLog, "[50, 50, 50, 50, 50,", "[50, 50, 50, 50, 1e30,"));
     },
     openLog,
     "the stem radius 1e\\+30 mm at slice 1, azimuth 1 is not plausible: the log's median radius is 50 mm",
     kRenderBoard},
    {"LogGranJsonRadiusImplausible",
     [](const fs::path& d) {
       writeText(d / "Gran_1_pith.json", "[[0, 0, 0], [0, 0, 100], [0, 0, 200]]");
       writeText(d / "Gran_1_radii.json", "[[100, 100, 100], [100, 100, 100], [100, 100, 1e30]]");
       writeText(d / "Gran_1_knots.json", "[]");
       return d / "Gran_1_radii.json";
     },
     [](const fs::path& p) { openLog(p.parent_path()); },
     "the stem radius 1e\\+30 mm at slice 2, azimuth 2 is not plausible",
     "render-board {dir} --out {out}/board.png --res 64"},
    {"LogMapsMissing",
     [](const fs::path& d) {
       writeText(d / "map_params.json", "[10, 100, 1000, 1]");
       return d;
     },
     openLog, "missing log map .*pith_and_radius_map.bmp",
     "render-board {file} --out {out}/board.png --res 64"},
    {"LogMapsKnotCountHuge",
     [](const fs::path& d) {
       writeText(d / "map_params.json", "[10, 100, 1000, 1e12]");
       return d / "map_params.json";
     },
     [](const fs::path& p) { openLog(p.parent_path()); }, "knot count must be a whole number from 0 to",
     "render-board {dir} --out {out}/board.png --res 64"},
    // --- ring contours and fits ---
    {"FitWithAnEmptyContourSet",
     [](const fs::path& d) {
       writeSample(d);
       for (const char* face : {"A", "B", "C", "D", "E", "F"})
         writeImage(d / (std::string(face) + "_arl.png"), Image(16, 16, 1));
       return d;
     },
     nullptr, "too few ring contours to fit the growth field: 0 on 0 faces",
     "fit {dir} --out {out}/fit.kerf --ignore-anatomy"},
    {"FitWithAllContoursOnOneFace",
     [](const fs::path& d) {
       // Only face A has a photo: the fit would detect rings on any other face's photo.
       writePhoto(d / "A_col.png", 16, 16);
       writeImage(d / "A_arl.png", ringImage(128, {-40.0f, 60.0f}, 12.0f));
       return d;
     },
     nullptr, "too few ring contours to fit the growth field: [0-9]+ on 1 faces",
     "fit {dir} --out {out}/fit.kerf --ignore-anatomy"},
    // --- meshes for a textured part ---
    {"MeshNonManifold",
     [](const fs::path& d) {
       writeText(d / "two_cubes.obj", kTwoCubesObj);
       return d / "two_cubes.obj";
     },
     [](const fs::path& p) { (void)loadMesh(p); },
     "is not the surface of a solid: 1 edge is shared by more than two triangles \\(e.g. at 1, 1, 0.5",
     kExportPart},
    {"MeshWithoutFaces",
     [](const fs::path& d) {
       writeText(d / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
       return d / "points.obj";
     },
     [](const fs::path& p) { (void)loadMesh(p); }, "has no faces", kExportPart},
    {"MeshOfZeroAreaTriangles",  // issue 21: such a part was exported
     [](const fs::path& d) {
       writeText(d / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 2 3 4\nf 1 2 4\n");
       return d / "flat.obj";
     },
     [](const fs::path& p) { (void)loadMesh(p); }, "has no area: all its 3 triangles are degenerate",
     kExportPart},
    // --- outputs ---
    {"OutputFolderMissing", [](const fs::path& d) { return d / "no-such-folder"; }, nullptr,
     "folder .*no-such-folder does not exist", "export {dir}/../demo.kerf --face A --out {file}/A.png"},
};

class Catalogue : public ::testing::TestWithParam<BadInput> {};

}  // namespace

TEST_P(Catalogue, RefusedWithAMessageNamingTheFileAndTheProblem) {
  const BadInput& c = GetParam();
  const fs::path root = fs::path(KERF_TEST_ARTIFACTS) / "bad_inputs";
  const fs::path dir = root / c.name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  if (!fs::exists(root / "demo.kerf")) saveProject(Project(), root / "demo.kerf");
  const fs::path input = c.make(dir);
  const std::string name = input.filename().string();

  if (c.open) {
    std::string message;
    try {
      c.open(input);
    } catch (const InputError& e) {
      message = e.what();
    }
    ASSERT_FALSE(message.empty()) << c.name << ": opened without an error";
    EXPECT_NE(message.find(name), std::string::npos)
        << "the message does not name " << name << ": " << message;
    EXPECT_TRUE(std::regex_search(message, std::regex(c.problem))) << message;
  }
  if (c.cli) {
    const fs::path out = dir / "out";
    std::string arguments = replaceAll(c.cli, "{file}", input.string());
    arguments = replaceAll(replaceAll(arguments, "{dir}", dir.string()), "{out}", out.string());
    const CliResult r = runCli(arguments);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    const std::size_t at = r.output.find("kerf-cli: error: ");
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_NE(r.output.find(name, at), std::string::npos)
        << "kerf-cli does not name " << name << ": " << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(c.problem))) << r.output;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << "kerf-cli wrote output for a bad input";
  }
}

INSTANTIATE_TEST_SUITE_P(BadInputs, Catalogue, ::testing::ValuesIn(kCatalogue),
                         [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });
