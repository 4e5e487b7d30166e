#pragma once
// Reading tree logs (docs/knots.md):
//  - the CT-measured "Gran_1" log of Larsson et al. 2022 in its two forms (shared/data/logs/spruce-gran1):
//    its JSON files (Gran_1_pith.json, Gran_1_radii.json, Gran_1_knots.json) and its image maps of
//    Sec. 4.4 (pith_and_radius_map.bmp, knot_*_map.bmp, map_params.json), read with OpenImageIO;
//  - Kerf's own log file (.kerflog, versioned JSON, written atomically).
// Both Gran_1 forms give the same LogModel up to the maps' 8-bit quantisation (tested).
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "field/log_model.hpp"

namespace kerf {

struct LogImportOptions {
  // The maps hold the outer radius after a box blur of +-50 mm x +-2 deg (their encoder); the JSON the raw
  // CT radii. Smoothing the JSON radii the same way (clamped at the log's ends) gives the same stem.
  bool smoothJsonRadii = true;
  // The shipped maps' start azimuths went through an operator-precedence slip of their encoder,
  // ((F + 2 pi) mod 2) pi instead of (F + 2 pi) mod 2 pi (shared/reference/PEER_SHADERS.md A.3). Off: the
  // JSON's true azimuths. On: the same (slipped) azimuths the maps hold, e.g. to compare the two forms.
  bool mapStartAzimuthSlip = false;
};

// Gran_1 JSON files in `folder`. Throws InputError naming the file on missing or malformed input.
LogModel importGranJson(const std::filesystem::path& folder, const LogImportOptions& options = {});
// Gran_1 image maps in `folder`. Throws InputError naming the file.
LogModel importGranMaps(const std::filesystem::path& folder);
// The 1D colour map wood_bar_color.bmp (middle row); empty when the file is absent. Throws on a bad file.
WoodColorMap importColorMapImage(const std::filesystem::path& path);

// Kerf's log file: {"format": "kerf-log", "version": 1, ...}; see docs/knots.md.
void saveLogFile(const LogModel& log, const std::filesystem::path& path);
LogModel loadLogFile(const std::filesystem::path& path);
// The same JSON as a value (a project embeds it under "log"); `where` names the source in errors.
nlohmann::json logToJson(const LogModel& log);
LogModel logFromJson(const nlohmann::json& json, const std::string& where);

// A log from a path: a Kerf log file, or a folder with Gran_1 JSON files (else its maps); the folder's
// wood_bar_color.bmp becomes the log's colour map when present.
LogModel loadLog(const std::filesystem::path& path);

}  // namespace kerf
