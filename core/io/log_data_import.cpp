#include "io/log_data_import.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/json_file.hpp"
#include "util/error.hpp"
#include "util/parse_number.hpp"

namespace kerf {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kTwoPi = 2.0f * kPi;
constexpr int kMapDistanceSamples = 32;  // knot maps: 32 columns over [0, rmax) (Sec. 4.4.2)
constexpr const char* kLogFormat = "kerf-log";
constexpr int kLogVersion = 1;

json readLogJson(const fs::path& path) {
  return readJsonFile(path, "log file");
}

float number(const json& v, const std::string& what) {
  if (!v.is_number()) throw InputError(what + " must be a number");
  return checkedNumber<float>(v.get<double>(), what);
}

// A count (slices, azimuths, knots): a whole number in [lo, hi], checked before any conversion to int.
int count(const json& v, const std::string& what, int lo, int hi) {
  if (!v.is_number()) throw InputError(what + " must be a number");
  const double n = v.get<double>();
  if (!(n >= lo && n <= hi) || n != std::floor(n)) {
    throw InputError(what + " must be a whole number from " + std::to_string(lo) + " to " +
                     std::to_string(hi));
  }
  return static_cast<int>(n);
}

// validate(log) names no file; the readers add theirs.
void validateFrom(const LogModel& log, const std::string& where) {
  try {
    validate(log);
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
}

const json& array(const json& v, const std::string& what, std::size_t minSize = 0) {
  if (!v.is_array() || v.size() < minSize) {
    throw InputError(what + " must be an array of at least " + std::to_string(minSize) + " entries");
  }
  return v;
}

// The knot distance grid of both Gran_1 forms: the maps' 32 columns, d_j = j rmax / 32.
float mapDistanceStep(float rmax) {
  return rmax / static_cast<float>(kMapDistanceSamples);
}

Image readMap(const fs::path& path) {
  if (!fs::exists(path)) throw InputError("missing log map " + path.string());
  return readImage(path);
}

// 8-bit channel value of a map pixel (OpenImageIO gives v / 255).
inline float byteAt(const Image& img, int x, int y, int c) {
  return std::round(img.pixel(x, y)[c] * 255.0f);
}
// The encoder truncated to 8 bits: the middle of the bin is the best estimate (0 stays 0).
inline float binCentre(float byte) {
  return byte > 0.0f ? byte + 0.5f : 0.0f;
}

}  // namespace

LogModel importGranJson(const fs::path& folder, const LogImportOptions& options) {
  if (!fs::is_directory(folder)) throw InputError("log folder " + folder.string() + " does not exist");
  const fs::path pithPath = folder / "Gran_1_pith.json", radiiPath = folder / "Gran_1_radii.json",
                 knotsPath = folder / "Gran_1_knots.json";
  const json pith = readLogJson(pithPath), radii = readLogJson(radiiPath), knots = readLogJson(knotsPath);
  LogModel log;
  log.name = folder.filename().string();
  Stem& stem = log.stem;
  array(pith, pithPath.string(), 2);
  const int slices = static_cast<int>(pith.size());
  std::vector<float> z(slices);
  stem.pith.resize(slices);
  for (int i = 0; i < slices; ++i) {
    const std::string what = pithPath.string() + " row " + std::to_string(i);
    const json& row = array(pith[i], what, 3);
    stem.pith[i] = glm::vec2(number(row[0], what), number(row[1], what));
    z[i] = number(row[2], what);
  }
  stem.heightStep = z[1] - z[0];
  for (int i = 1; i < slices; ++i) {
    if (std::abs(z[i] - z[0] - stem.heightStep * static_cast<float>(i)) > 1e-3f * stem.heightStep + 1e-4f) {
      throw InputError(pithPath.string() + ": slices must be evenly spaced in z (row " + std::to_string(i) +
                       ")");
    }
  }
  if (!(stem.heightStep > 0.0f)) throw InputError(pithPath.string() + ": z must increase from row to row");
  // Kerf's log frame: z from the first slice, x, y from the pith of the middle slice (as the maps store it).
  const glm::vec2 middle = stem.pith[slices / 2];
  for (glm::vec2& p : stem.pith) p -= middle;

  array(radii, radiiPath.string(), static_cast<std::size_t>(slices));
  if (static_cast<int>(radii.size()) != slices) {
    throw InputError(radiiPath.string() + " has " + std::to_string(radii.size()) + " rows; the pith has " +
                     std::to_string(slices) + " slices");
  }
  stem.azimuths = static_cast<int>(array(radii[0], radiiPath.string() + " row 0", 3).size());
  std::vector<float> raw(static_cast<std::size_t>(slices) * stem.azimuths);
  for (int i = 0; i < slices; ++i) {
    const std::string what = radiiPath.string() + " row " + std::to_string(i);
    const json& row = array(radii[i], what, static_cast<std::size_t>(stem.azimuths));
    if (static_cast<int>(row.size()) != stem.azimuths)
      throw InputError(what + " has a different length than row 0");
    for (int j = 0; j < stem.azimuths; ++j)
      raw[static_cast<std::size_t>(i) * stem.azimuths + j] = number(row[j], what);
  }
  float rmin = *std::min_element(raw.begin(), raw.end()), rmax = *std::max_element(raw.begin(), raw.end());
  if (!(rmin > 0.0f)) throw InputError(radiiPath.string() + ": radii must be positive");
  // Before the smoothing, which would spread one wrong sample over its neighbours.
  checkPlausibleRadii(raw, stem.azimuths, radiiPath.string());
  if (options.smoothJsonRadii) {
    // The maps' box blur: +-5 slices (clamped here at the ends) x +-2 degrees (periodic), separable:
    // along the azimuth, then along the slices (16 reads per sample instead of 55).
    const int hz = 5, ha = std::max(1, stem.azimuths / 180), n = stem.azimuths;
    std::vector<double> across(raw.size());
    for (int i = 0; i < slices; ++i)
      for (int j = 0; j < n; ++j) {
        double sum = 0;
        for (int dj = -ha; dj <= ha; ++dj)
          sum += raw[static_cast<std::size_t>(i) * n + ((j + dj) % n + n) % n];
        across[static_cast<std::size_t>(i) * n + j] = sum;
      }
    const double count = (2.0 * hz + 1) * (2.0 * ha + 1);
    stem.radii.resize(raw.size());
    for (int i = 0; i < slices; ++i)
      for (int j = 0; j < n; ++j) {
        double sum = 0;
        for (int di = -hz; di <= hz; ++di)
          sum += across[static_cast<std::size_t>(std::clamp(i + di, 0, slices - 1)) * n + j];
        stem.radii[static_cast<std::size_t>(i) * n + j] = static_cast<float>(sum / count);
      }
  } else {
    stem.radii = raw;
  }

  // Knots, one row of 9 per knot [A, B, C, D, E, F, G, H, I] (Groenlund et al.; PEER_SHADERS.md A.3):
  // start height C, vertical course D sqrt(d) + E d, azimuth F + G ln d, broken off at H, dead from I.
  checkLogKnotCount(array(knots, knotsPath.string()).size(), knotsPath.string());
  const float step = mapDistanceStep(rmax);
  for (std::size_t k = 0; k < knots.size(); ++k) {
    const std::string what = knotsPath.string() + " knot " + std::to_string(k);
    const json& row = array(knots[k], what, 9);
    float v[9];
    for (int c = 0; c < 9; ++c) v[c] = number(row[c], what);
    const float C = v[2], D = v[3], E = v[4], F = v[5], G = v[6], H = v[7], I = v[8];
    Knot knot;
    knot.distanceStep = step;
    knot.heights.resize(kMapDistanceSamples);
    knot.azimuths.resize(kMapDistanceSamples);
    float start =
        options.mapStartAzimuthSlip ? std::fmod(F + kTwoPi, 2.0f) * kPi : std::fmod(F + kTwoPi, kTwoPi);
    for (int j = 0; j < kMapDistanceSamples; ++j) {
      const float d = step * static_cast<float>(j);
      // The data's vertical term has the sign that makes branches sink; spruce branches rise from the pith,
      // as the authors' shader renders them, so Kerf takes it with the opposite sign (docs/knots.md).
      knot.heights[j] = C - (D * std::sqrt(d) + E * d);
      knot.azimuths[j] = start + G * std::log(std::max(d, 1.0f));
    }
    knot.endDistance = H;
    knot.deathDistance = I;
    log.knots.push_back(std::move(knot));
  }
  validateFrom(log, "log folder " + folder.string());
  return log;
}

LogModel importGranMaps(const fs::path& folder) {
  if (!fs::is_directory(folder)) throw InputError("log folder " + folder.string() + " does not exist");
  const fs::path paramsPath = folder / "map_params.json";
  const json params = readLogJson(paramsPath);
  array(params, paramsPath.string(), 4);
  const float rmin = number(params[0], paramsPath.string() + " rmin"),
              rmax = number(params[1], paramsPath.string() + " rmax"),
              hmax = number(params[2], paramsPath.string() + " hmax");
  // The knot budget of every log (field/log_model.hpp), before any knot map row is read.
  const int count =
      kerf::count(params[3], paramsPath.string() + " knot count", 0, static_cast<int>(kMaxLogKnots));
  if (!(rmin > 0.0f) || !(rmax > rmin) || !(hmax > 0.0f)) {
    throw InputError(paramsPath.string() + " must hold [rmin > 0, rmax > rmin, hmax > 0, knots >= 0]");
  }
  LogModel log;
  log.name = folder.filename().string();
  // Stem map (Table 1): x = azimuth (2 deg per column after the encoder's 360 -> 180 resize), y = slice;
  // R, G = pith offset from the middle slice in [-rmin/2, rmin/2]; B = radius in [rmin, rmax].
  const fs::path stemPath = folder / "pith_and_radius_map.bmp";
  const Image stemMap = readMap(stemPath);
  Stem& stem = log.stem;
  const int slices = stemMap.height, columns = stemMap.width;
  if (slices < 2 || columns < 3) throw InputError(stemPath.string() + " is too small for a stem map");
  stem.heightStep = hmax / static_cast<float>(slices);
  stem.azimuths = 360;
  stem.pith.resize(slices);
  stem.radii.resize(static_cast<std::size_t>(slices) * stem.azimuths);
  const float degPerColumn = 360.0f / static_cast<float>(columns);
  std::vector<float> rowRadius(columns);
  for (int i = 0; i < slices; ++i) {
    const float rx = binCentre(byteAt(stemMap, columns / 2, i, 0)),
                gy = binCentre(byteAt(stemMap, columns / 2, i, 1));
    stem.pith[i] = glm::vec2((rx / 255.0f - 0.5f) * rmin, (gy / 255.0f - 0.5f) * rmin);
    for (int c = 0; c < columns; ++c) {
      rowRadius[c] = rmin + binCentre(byteAt(stemMap, c, i, 2)) / 255.0f * (rmax - rmin);
    }
    // Column c of the resized map is centred on input degree c * 2 + 0.5: resample at whole degrees.
    for (int j = 0; j < stem.azimuths; ++j) {
      float u = (static_cast<float>(j) - 0.5f * (degPerColumn - 1.0f)) / degPerColumn;
      u -= std::floor(u / static_cast<float>(columns)) * static_cast<float>(columns);
      const int c0 = static_cast<int>(u) % columns, c1 = (c0 + 1) % columns;
      const float f = u - std::floor(u);
      stem.radii[static_cast<std::size_t>(i) * stem.azimuths + j] =
          rowRadius[c0] + f * (rowRadius[c1] - rowRadius[c0]);
    }
  }
  // Knot maps (Table 2): x = distance from the pith (32 columns over [0, rmax)), 4 rows per knot.
  const fs::path heightPath = folder / "knot_height_map.bmp",
                 orientPath = folder / "knot_orientation_map.bmp", statePath = folder / "knot_state_map.bmp";
  const Image heightMap = readMap(heightPath), orientMap = readMap(orientPath), stateMap = readMap(statePath);
  for (const auto* m : {&heightMap, &orientMap, &stateMap}) {
    if (m->width != kMapDistanceSamples || m->height < 4 * count) {
      throw InputError("knot maps in " + folder.string() + " must be 32 wide and 4 rows per knot (" +
                       std::to_string(count) + " knots)");
    }
  }
  const float step = mapDistanceStep(rmax);
  for (int k = 0; k < count; ++k) {
    const int y = 4 * k + 1;
    Knot knot;
    knot.distanceStep = step;
    knot.heights.resize(kMapDistanceSamples);
    knot.azimuths.resize(kMapDistanceSamples);
    const float start = binCentre(byteAt(heightMap, 0, y, 0)) / 255.0f * hmax;
    const float omega0 = byteAt(orientMap, 0, y, 0) / 255.0f * kTwoPi;
    for (int j = 0; j < kMapDistanceSamples; ++j) {
      // z = start + z+ - z- (Table 2), with the data's vertical sign turned as in importGranJson.
      const float up = binCentre(byteAt(heightMap, j, y, 1)), down = binCentre(byteAt(heightMap, j, y, 2));
      knot.heights[j] = start - (up - down) / 255.0f * rmin;
      // omega = start + ccw - cw (Table 2), twist in [-pi/2, pi/2].
      const float ccw = binCentre(byteAt(orientMap, j, y, 1)), cw = binCentre(byteAt(orientMap, j, y, 2));
      knot.azimuths[j] = omega0 + (ccw - cw) / 255.0f * (0.5f * kPi);
    }
    knot.deathDistance = binCentre(byteAt(stateMap, 0, y, 1)) / 255.0f * rmax;
    knot.endDistance = std::numeric_limits<float>::infinity();  // not encoded in the maps
    log.knots.push_back(std::move(knot));
  }
  validateFrom(log, "log folder " + folder.string());
  return log;
}

WoodColorMap importColorMapImage(const fs::path& path) {
  WoodColorMap map;
  if (!fs::exists(path)) return map;
  const Image img = readImage(path);
  const int y = img.height / 2;
  map.colors.resize(img.width);
  for (int x = 0; x < img.width; ++x) {
    const float* p = img.pixel(x, y);
    map.colors[x] = glm::vec3(p[0], p[1], p[2]);
  }
  return map;
}

namespace {

json floats(const std::vector<float>& v) {
  json out = json::array();
  for (float f : v) out.push_back(f);
  return out;
}

json optionalDistance(float d) {
  return std::isfinite(d) ? json(d) : json(nullptr);
}

float readOptionalDistance(const json& v, const std::string& what) {
  return v.is_null() ? std::numeric_limits<float>::infinity() : number(v, what);
}

std::vector<float> readFloats(const json& v, const std::string& what) {
  array(v, what);
  std::vector<float> out;
  out.reserve(v.size());
  for (const json& x : v) out.push_back(number(x, what));
  return out;
}

}  // namespace

json logToJson(const LogModel& log) {
  validate(log);
  json pith = json::array();
  for (const glm::vec2& p : log.stem.pith) pith.push_back({p.x, p.y});
  json knots = json::array();
  for (const Knot& k : log.knots) {
    knots.push_back({{"distance_step_mm", k.distanceStep},
                     {"height_mm", floats(k.heights)},
                     {"azimuth_rad", floats(k.azimuths)},
                     {"death_distance_mm", optionalDistance(k.deathDistance)},
                     {"end_distance_mm", optionalDistance(k.endDistance)}});
  }
  json out = {{"format", kLogFormat},
              {"version", kLogVersion},
              {"name", log.name},
              {"stem",
               {{"height_step_mm", log.stem.heightStep},
                {"azimuths", log.stem.azimuths},
                {"pith_mm", pith},
                {"radii_mm", floats(log.stem.radii)}}},
              {"knots", knots}};
  if (!log.colorMap.empty()) {
    json colors = json::array();
    for (const glm::vec3& c : log.colorMap.colors) colors.push_back({c.x, c.y, c.z});
    out["color_map"] = colors;
  }
  return out;
}

void saveLogFile(const LogModel& log, const fs::path& path) {
  writeTextAtomically(path, logToJson(log).dump());
}

LogModel logFromJson(const json& in, const std::string& where) {
  if (!in.is_object() || !in.contains("format") || in["format"] != kLogFormat) {
    throw InputError(where + " is not a Kerf log (missing \"format\": \"kerf-log\")");
  }
  if (!in.contains("version") || !in["version"].is_number_integer())
    throw InputError(where + " has no format version");
  const int version = checkedNumber<int>(in["version"].get<double>(), "version");
  if (version > kLogVersion) {
    throw InputError(where + " was written by a newer Kerf (log format version " + std::to_string(version) +
                     "); this Kerf reads versions up to " + std::to_string(kLogVersion));
  }
  if (version < 1) throw InputError(where + ": unknown log format version " + std::to_string(version));
  LogModel log;
  const json name = in.value("name", json(""));
  if (!name.is_string()) throw InputError(where + ": \"name\" must be a string");
  log.name = name.get<std::string>();
  if (!in.contains("stem") || !in["stem"].is_object()) throw InputError(where + " has no \"stem\" object");
  const json& stem = in["stem"];
  log.stem.heightStep = number(stem.value("height_step_mm", json()), where + ": stem.height_step_mm");
  log.stem.azimuths = count(stem.value("azimuths", json()), where + ": stem.azimuths", 3, 1 << 20);
  const json pith = stem.value("pith_mm", json());
  for (const json& p : array(pith, where + ": stem.pith_mm", 2)) {
    const json& xy = array(p, where + ": stem.pith_mm entry", 2);
    log.stem.pith.emplace_back(number(xy[0], where + ": pith x"), number(xy[1], where + ": pith y"));
  }
  log.stem.radii = readFloats(stem.value("radii_mm", json()), where + ": stem.radii_mm");
  const json knots = in.value("knots", json::array());
  checkLogKnotCount(array(knots, where + ": knots").size(), where);
  for (std::size_t k = 0; k < knots.size(); ++k) {
    const json& j = knots[k];
    const std::string what = where + ": knot " + std::to_string(k);
    if (!j.is_object()) throw InputError(what + " must be an object");
    Knot knot;
    knot.distanceStep = number(j.value("distance_step_mm", json()), what + " distance_step_mm");
    knot.heights = readFloats(j.value("height_mm", json()), what + " height_mm");
    knot.azimuths = readFloats(j.value("azimuth_rad", json()), what + " azimuth_rad");
    knot.deathDistance =
        readOptionalDistance(j.value("death_distance_mm", json()), what + " death_distance_mm");
    knot.endDistance = readOptionalDistance(j.value("end_distance_mm", json()), what + " end_distance_mm");
    log.knots.push_back(std::move(knot));
  }
  if (in.contains("color_map")) {
    for (const json& c : array(in["color_map"], where + ": color_map")) {
      const json& rgb = array(c, where + ": color_map entry", 3);
      log.colorMap.colors.emplace_back(number(rgb[0], where + ": colour"), number(rgb[1], where + ": colour"),
                                       number(rgb[2], where + ": colour"));
    }
  }
  validateFrom(log, where);
  return log;
}

LogModel loadLogFile(const fs::path& path) {
  return logFromJson(readLogJson(path), "log file " + path.string());
}

LogModel loadLog(const fs::path& path) {
  if (!fs::exists(path)) throw InputError("cannot open log " + path.string() + ": no such file or folder");
  if (!fs::is_directory(path)) return loadLogFile(path);
  LogModel log = fs::exists(path / "Gran_1_knots.json") ? importGranJson(path) : importGranMaps(path);
  log.colorMap = importColorMapImage(path / "wood_bar_color.bmp");
  return log;
}

}  // namespace kerf
