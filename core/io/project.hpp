#pragma once
// A Kerf document: the block, its face photos, every procedural parameter and (when fitted or edited)
// the growth-rate grid. Stored as a versioned JSON `.kerf` file with photo paths relative to it.
#include <array>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "field/block_knots.hpp"
#include "field/growth_rates.hpp"
#include "field/ring_uncertainty.hpp"
#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"
#include "geometry/face_set.hpp"
#include "io/cut_photo.hpp"
#include "io/project_log.hpp"
#include "params/parameter_json.hpp"  // the parameters alone, as projects store them
#include "params/parameter_schema.hpp"
#include "rings/annotations.hpp"

namespace kerf {

inline constexpr int kProjectFormatVersion = 1;
inline constexpr const char* kProjectFormatName = "kerf-project";

// How a project's surfaces are coloured (issue 17): by the procedural model, or photo-true, made of the
// project's own face photos re-grown along the fitted field (appearance/photo_true_appearance.hpp).
enum class Appearance { Procedural, Photo };
const char* appearanceName(Appearance appearance);  // "procedural", "photo"
// "procedural" or "photo"; InputError otherwise.
Appearance appearanceFromName(const std::string& name);

struct Project {
  Block block;
  WoodParameters params;
  // Explicit growth rates (fitted, or saved from an edit). Without them the rates are synthesised
  // from the growth.* parameters (synthesizeGrowthRates).
  std::optional<GrowthRates> rates;
  // Face photos A..F; empty when a face has none. Absolute paths in memory.
  std::array<std::filesystem::path, 6> facePhotos;
  // The editor's cut plane, kept with the project so a saved view opens as it was left.
  std::optional<CutPlaneSetting> cutPlane;
  bool cutEnabled = false;
  // The user's ring traces and knot marks (face mm; core/rings/annotations.hpp). Saved under the optional
  // key "annotations" (core/io/annotations_json.hpp).
  Annotations annotations;
  // A log and the board cut from it (optional key "log"; io/project_log.hpp): the editor then shows the
  // board's faces, rendered with the knot model.
  std::optional<ProjectLog> log;
  // Knots in the block's growth field (Mokume Sec. 5.2.4; fitted from knot marks or edited), optional key
  // "knots" (io/block_knots_json.hpp).
  std::vector<BlockKnot> knots;
  // How sure the fit is inside the block (field/ring_uncertainty.hpp), when estimated; it belongs to the
  // field whose fingerprint it holds (ringUncertaintyOf). Optional key "ring_uncertainty".
  std::optional<RingUncertainty> ringUncertainty;
  // Faces held out of every fit (leave-one-face-out, docs/fitting.md): ring detection, the growth-field
  // fit, the colours and the texture use nothing of their photos, so their rendering is a prediction.
  // Optional key "held_out_faces", the letters ("C"); absent when empty.
  FaceSet heldOutFaces;
  // Optional key "appearance" ("photo"); absent when procedural.
  Appearance appearance = Appearance::Procedural;
  // A photo of the real cut, aligned to the model's cut on its plane (io/cut_photo.hpp). Optional key
  // "cut_photo"; its file relative to the project where it can be.
  std::optional<CutPhoto> cutPhoto;

  // The ring uncertainty when it belongs to the current field (not stale after a refit or an edit).
  const RingUncertainty* currentRingUncertainty() const;

  GrowthRates effectiveRates() const { return rates ? *rates : synthesizeGrowthRates(params, block); }
};

// JSON (de)serialisation. Paths are written relative to `baseDir` and resolved against it on reading.
// Missing parameters take their defaults; unknown ones are refused, as are NaNs, out-of-range values,
// and format versions this Kerf does not read. Errors are InputError with a message that names the field.
nlohmann::json projectToJson(const Project& project, const std::filesystem::path& baseDir);
Project projectFromJson(const nlohmann::json& json, const std::filesystem::path& baseDir);

nlohmann::json growthRatesToJson(const GrowthRates& rates);
GrowthRates growthRatesFromJson(const nlohmann::json& json);  // throws InputError

// Files. saveProject writes atomically.
Project loadProject(const std::filesystem::path& file);
void saveProject(const Project& project, const std::filesystem::path& file);

// A Mokume-style sample folder: A_col.png .. F_col.png (other extensions accepted) on a 40 mm cube, or
// on the block of the folder's block.json ({"size_mm": [x, y, z]}) when there is one and no size is
// given. Numbered ring images <F>_ann.png and knot marks <F>_knot.png, when present, become the
// project's annotations. Faces that are missing stay empty. InputError naming the file: a folder
// without any face photo, an unreadable image, photos whose sizes disagree along a shared block axis,
// a non-square photo for a cube, a photo or annotation image with other proportions than its face
// (core/io/sample_folder.hpp).
Project projectFromSampleFolder(const std::filesystem::path& folder,
                                std::optional<glm::vec3> blockSizeMm = std::nullopt);

// A project file or a sample folder, whichever `path` is.
Project loadDocument(const std::filesystem::path& path);

}  // namespace kerf
