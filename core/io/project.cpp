#include "io/project.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/annotations_json.hpp"
#include "io/atomic_file.hpp"
#include "io/block_knots_json.hpp"
#include "io/json_file.hpp"
#include "io/mokume_annotation_files.hpp"
#include "io/ring_uncertainty_json.hpp"
#include "io/sample_folder.hpp"
#include "params/parameter_json.hpp"
#include "util/error.hpp"
#include "util/parse_number.hpp"

namespace kerf {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char* kVersionString = "0.1.0";

// A grid size: a whole number that an int holds (2^32 + 8 must not wrap to 8, 8.9 not become 8).
int readCount(const json& value, const std::string& what) {
  if (!value.is_number()) throw InputError(what + " must be a whole number, got " + describeJson(value));
  return checkedNumber<int>(value.get<double>(), what, 0, std::numeric_limits<int>::max());
}

json writeVec3(glm::vec3 v) {
  return json::array({v.x, v.y, v.z});
}

// nlohmann's message without its "[json.exception.parse_error.101] " prefix.
std::string jsonProblem(const json::exception& e) {
  const std::string what = e.what();
  const auto end = what.find("] ");
  return end == std::string::npos ? what : what.substr(end + 2);
}

}  // namespace

const char* appearanceName(Appearance appearance) {
  return appearance == Appearance::Photo ? "photo" : "procedural";
}

Appearance appearanceFromName(const std::string& name) {
  if (name == "photo") return Appearance::Photo;
  if (name == "procedural") return Appearance::Procedural;
  throw InputError("unknown appearance \"" + name + "\" (procedural or photo)");
}

json growthRatesToJson(const GrowthRates& g) {
  return {{"heights", g.heights},
          {"azimuths", g.azimuths},
          {"radii", g.radii},
          {"height_range_mm", json::array({g.heightMin, g.heightMax})},
          {"radius_range_mm", json::array({g.radiusMin, g.radiusMax})},
          {"azimuth_range_rad", json::array({g.azimuthMin, g.azimuthMax})},
          {"rates", g.rates}};
}

GrowthRates growthRatesFromJson(const json& in) {
  if (!in.is_object()) throw InputError("\"growth_rates\" must be an object");
  try {
    GrowthRates g;
    g.heights = readCount(in.at("heights"), "growth_rates.heights");
    g.azimuths = readCount(in.at("azimuths"), "growth_rates.azimuths");
    g.radii = readCount(in.at("radii"), "growth_rates.radii");
    const json& hr = in.at("height_range_mm");
    const json& rr = in.at("radius_range_mm");
    if (!hr.is_array() || hr.size() != 2 || !rr.is_array() || rr.size() != 2) {
      throw InputError("growth_rates ranges must be [min, max] pairs");
    }
    g.heightMin = readJsonNumber(hr[0], "growth_rates.height_range_mm");
    g.heightMax = readJsonNumber(hr[1], "growth_rates.height_range_mm");
    g.radiusMin = readJsonNumber(rr[0], "growth_rates.radius_range_mm");
    g.radiusMax = readJsonNumber(rr[1], "growth_rates.radius_range_mm");
    if (in.contains("azimuth_range_rad")) {  // absent in older files: the full circle
      const json& ar = in.at("azimuth_range_rad");
      if (!ar.is_array() || ar.size() != 2) throw InputError("growth_rates ranges must be [min, max] pairs");
      g.azimuthMin = readJsonNumber(ar[0], "growth_rates.azimuth_range_rad");
      g.azimuthMax = readJsonNumber(ar[1], "growth_rates.azimuth_range_rad");
    }
    const json& rates = in.at("rates");
    if (!rates.is_array()) throw InputError("growth_rates.rates must be a list of numbers");
    g.rates.reserve(rates.size());
    for (const json& r : rates) g.rates.push_back(readJsonNumber(r, "growth_rates.rates entry"));
    g.validate();
    return g;
  } catch (const json::exception& e) {
    throw InputError(std::string("malformed growth_rates: ") + e.what());
  }
}

const RingUncertainty* Project::currentRingUncertainty() const {
  if (!ringUncertainty || ringUncertainty->empty()) return nullptr;
  return ringUncertainty->field == fieldFingerprint(params, effectiveRates(), knots) ? &*ringUncertainty
                                                                                     : nullptr;
}

json projectToJson(const Project& project, const fs::path& baseDir) {
  json faces = json::object();
  for (FaceId face : kAllFaces) {
    const fs::path& photo = project.facePhotos[faceIndex(face)];
    if (photo.empty()) continue;
    faces[std::string(1, faceLetter(face))] = {
        {"photo", photo.lexically_proximate(baseDir).generic_string()}};
  }
  json out = {{"format", kProjectFormatName},
              {"version", kProjectFormatVersion},
              {"generator", std::string("Kerf ") + kVersionString},
              {"block", {{"size_mm", writeVec3(project.block.size())}}},
              {"faces", faces},
              {"parameters", parametersToJson(project.params)}};
  if (project.rates) out["growth_rates"] = growthRatesToJson(*project.rates);
  if (!project.annotations.empty()) out["annotations"] = annotationsToJson(project.annotations);
  if (project.log) out["log"] = projectLogToJson(*project.log);
  if (!project.knots.empty()) out["knots"] = blockKnotsToJson(project.knots);
  if (project.ringUncertainty) out["ring_uncertainty"] = ringUncertaintyToJson(*project.ringUncertainty);
  if (!project.heldOutFaces.empty()) out["held_out_faces"] = project.heldOutFaces.letters();
  if (project.appearance != Appearance::Procedural) out["appearance"] = appearanceName(project.appearance);
  if (project.cutPhoto) out["cut_photo"] = cutPhotoToJson(*project.cutPhoto, baseDir);
  if (project.cutPlane) {
    out["view"] = {{"cut_plane",
                    {{"offset_mm", project.cutPlane->offsetMm},
                     {"azimuth_deg", project.cutPlane->azimuthDeg},
                     {"elevation_deg", project.cutPlane->elevationDeg},
                     {"enabled", project.cutEnabled}}}};
  }
  return out;
}

Project projectFromJson(const json& in, const fs::path& baseDir) {
  if (!in.is_object() || !in.contains("format") || in["format"] != kProjectFormatName) {
    throw InputError("not a Kerf project (missing \"format\": \"kerf-project\")");
  }
  if (!in.contains("version") || !in["version"].is_number_integer()) {
    throw InputError("the project has no format version");
  }
  const int version = checkedNumber<int>(in["version"].get<double>(), "version");
  if (version > kProjectFormatVersion) {
    throw InputError("the project was written by a newer Kerf (format version " + std::to_string(version) +
                     "); this Kerf reads format versions up to " + std::to_string(kProjectFormatVersion) +
                     ". Please update Kerf.");
  }
  if (version < 1) throw InputError("unknown project format version " + std::to_string(version));

  Project project;
  if (in.contains("block")) {
    const json& block = in["block"];
    if (!block.is_object() || !block.contains("size_mm"))
      throw InputError("\"block\" needs \"size_mm\": [x, y, z]");
    project.block = Block(readJsonVec3(block["size_mm"], "block.size_mm"));
  }
  if (in.contains("faces")) {
    const json& faces = in["faces"];
    if (!faces.is_object()) throw InputError("\"faces\" must be an object keyed A..F");
    for (const auto& [key, face] : faces.items()) {
      const auto id = key.size() == 1 ? faceFromLetter(key[0]) : std::nullopt;
      if (!id) throw InputError("unknown face \"" + key + "\" (faces are A..F)");
      if (!face.is_object() || !face.contains("photo") || !face["photo"].is_string()) {
        throw InputError("face " + key + " needs \"photo\": \"file name\"");
      }
      project.facePhotos[faceIndex(*id)] = (baseDir / face["photo"].get<std::string>()).lexically_normal();
    }
  }
  if (in.contains("parameters")) project.params = parametersFromJson(in["parameters"]);
  if (in.contains("growth_rates") && !in["growth_rates"].is_null()) {
    project.rates = growthRatesFromJson(in["growth_rates"]);
  }
  if (in.contains("annotations") && !in["annotations"].is_null()) {
    project.annotations = annotationsFromJson(in["annotations"], project.block);
  }
  if (in.contains("log") && !in["log"].is_null()) project.log = projectLogFromJson(in["log"]);
  if (in.contains("knots") && !in["knots"].is_null()) project.knots = blockKnotsFromJson(in["knots"]);
  if (in.contains("ring_uncertainty") && !in["ring_uncertainty"].is_null())
    project.ringUncertainty = ringUncertaintyFromJson(in["ring_uncertainty"]);
  if (in.contains("held_out_faces") && !in["held_out_faces"].is_null()) {
    const json& held = in["held_out_faces"];
    if (!held.is_string())
      throw InputError("\"held_out_faces\" must be a string of face letters, e.g. \"C\"");
    try {
      project.heldOutFaces = parseFaceSet(held.get<std::string>());
    } catch (const InputError& e) {
      throw InputError(std::string("held_out_faces: ") + e.what());
    }
  }
  if (in.contains("appearance") && !in["appearance"].is_null()) {
    if (!in["appearance"].is_string()) throw InputError("\"appearance\" must be \"procedural\" or \"photo\"");
    project.appearance = appearanceFromName(in["appearance"].get<std::string>());
  }
  if (in.contains("cut_photo") && !in["cut_photo"].is_null())
    project.cutPhoto = cutPhotoFromJson(in["cut_photo"], baseDir);
  if (in.contains("view") && in["view"].is_object() && in["view"].contains("cut_plane")) {
    const json& cut = in["view"]["cut_plane"];
    if (!cut.is_object()) throw InputError("\"view.cut_plane\" must be an object");
    CutPlaneSetting setting;
    setting.offsetMm = readJsonNumber(cut.value("offset_mm", json(0.0)), "view.cut_plane.offset_mm");
    setting.azimuthDeg = readJsonNumber(cut.value("azimuth_deg", json(0.0)), "view.cut_plane.azimuth_deg");
    setting.elevationDeg =
        readJsonNumber(cut.value("elevation_deg", json(0.0)), "view.cut_plane.elevation_deg");
    project.cutPlane = setting;
    const json enabled = cut.value("enabled", json(false));
    if (!enabled.is_boolean()) throw InputError("view.cut_plane.enabled must be true or false");
    project.cutEnabled = enabled.get<bool>();
  }
  return project;
}

Project loadProject(const fs::path& file) {
  const json in = readJsonFile(file, "project");
  try {
    return projectFromJson(in, fs::absolute(file).parent_path());
  } catch (const InputError& e) {
    throw InputError("project " + file.string() + ": " + e.what());
  } catch (const json::exception& e) {  // a value of the wrong type that a reader did not check itself
    throw InputError("project " + file.string() + ": a value has the wrong type (" + jsonProblem(e) + ")");
  }
}

void saveProject(const Project& project, const fs::path& file) {
  const fs::path base = fs::absolute(file).parent_path();
  writeTextAtomically(file, projectToJson(project, base).dump(2) + "\n");
}

Project projectFromSampleFolder(const fs::path& folder, std::optional<glm::vec3> blockSize) {
  if (!fs::is_directory(folder)) throw InputError("not a folder: " + folder.string());
  Project project;
  const std::optional<glm::vec3> fromFile = blockSize ? std::nullopt : readSampleBlockSize(folder);
  project.block = Block(blockSize ? *blockSize : fromFile.value_or(glm::vec3(40.0f)));
  project.facePhotos = findSampleFacePhotos(folder);
  const auto found = std::count_if(project.facePhotos.begin(), project.facePhotos.end(),
                                   [](const fs::path& photo) { return !photo.empty(); });
  if (found == 0) {
    throw InputError("folder " + folder.string() + " holds no face photos (expected A_col.png .. F_col.png)");
  }
  const MokumeAnnotationFiles annotationFiles = findMokumeAnnotationFiles(folder);
  validateSampleFolder(project.facePhotos, annotationFiles, project.block, blockSize || fromFile);
  if (annotationFiles.any()) project.annotations = readMokumeAnnotations(annotationFiles, project.block);
  return project;
}

Project loadDocument(const fs::path& path) {
  if (fs::is_directory(path)) return projectFromSampleFolder(path);
  return loadProject(path);
}

}  // namespace kerf
