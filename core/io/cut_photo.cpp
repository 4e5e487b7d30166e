#include "io/cut_photo.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "util/error.hpp"
#include "util/json_text.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

PlaneRect boundsOf(const CutPlaneSetting& setting, const Block& block) {
  const auto bounds = setting.plane().boundsInBlock(block);
  if (!bounds) throw InputError("the cut photo's plane does not pass through the block");
  return *bounds;
}

glm::vec2 readVec2(const json& value, const std::string& what) {
  if (!value.is_array() || value.size() != 2) throw InputError(what + " must be [x, y]");
  return {readJsonNumber(value[0], what + "[0]"), readJsonNumber(value[1], what + "[1]")};
}

}  // namespace

bool cutPhotoBelongsTo(const CutPhoto& photo, const CutPlaneSetting& setting) {
  return std::abs(photo.plane.offsetMm - setting.offsetMm) < 0.01f &&
         std::abs(photo.plane.azimuthDeg - setting.azimuthDeg) < 0.01f &&
         std::abs(photo.plane.elevationDeg - setting.elevationDeg) < 0.01f;
}

std::array<glm::vec2, 4> wholePhotoCorners(glm::ivec2 size) {
  const glm::vec2 s(size);
  return {glm::vec2(0.0f), glm::vec2(s.x, 0.0f), s, glm::vec2(0.0f, s.y)};
}

float cutPhotoPxPerMm(const CutPhoto& photo, glm::ivec2 photoSize, const Block& block, int maxSide) {
  const PlaneRect bounds = boundsOf(photo.plane, block);
  const glm::vec2 extent = bounds.max - bounds.min;
  validateCorners(photo.setup.corners, photoSize);
  const float own = photoResolution(photo.setup.corners, extent, photo.setup.rotationDegrees).x;
  const float cap = static_cast<float>(std::max(1, maxSide)) / std::max(extent.x, extent.y);
  return std::max(0.05f, std::min(own, cap));
}

Image rectifyCutPhoto(const Image& photo, const CutPhoto& cut, const Block& block, float pxPerMm) {
  // cutGrid's size, without core/appearance (a folder above this one).
  const PlaneRect bounds = boundsOf(cut.plane, block);
  const glm::vec2 extent = bounds.max - bounds.min;
  const glm::ivec2 size(pixelsAlong(std::ceil(double(extent.x) * pxPerMm - 1e-3)),
                        pixelsAlong(std::ceil(double(extent.y) * pxPerMm - 1e-3)));
  return rectifyFace(photo, cut.setup, size);
}

json cutPhotoToJson(const CutPhoto& photo, const fs::path& baseDir) {
  json corners = json::array();
  for (glm::vec2 c : photo.setup.corners) corners.push_back({c.x, c.y});
  return {{"photo", photo.setup.source.lexically_proximate(baseDir).generic_string()},
          {"corners_px", corners},
          {"rotation_deg", photo.setup.rotationDegrees},
          {"mirror", photo.setup.flip},
          {"cut_plane",
           {{"offset_mm", photo.plane.offsetMm},
            {"azimuth_deg", photo.plane.azimuthDeg},
            {"elevation_deg", photo.plane.elevationDeg}}}};
}

CutPhoto cutPhotoFromJson(const json& in, const fs::path& baseDir) {
  if (!in.is_object()) throw InputError("\"cut_photo\" must be an object");
  CutPhoto photo;
  if (!in.contains("photo") || !in["photo"].is_string() || in["photo"].get<std::string>().empty())
    throw InputError("cut_photo needs \"photo\": \"file name\"");
  photo.setup.source = (baseDir / in["photo"].get<std::string>()).lexically_normal();
  const json corners = in.value("corners_px", json());
  if (!corners.is_array() || corners.size() != 4)
    throw InputError("cut_photo.corners_px must be four [x, y] photo pixels");
  for (int k = 0; k < 4; ++k)
    photo.setup.corners[k] = readVec2(corners[k], "cut_photo.corners_px[" + std::to_string(k) + "]");
  const float rotation = readJsonNumber(in.value("rotation_deg", json(0)), "cut_photo.rotation_deg");
  if (rotation != std::round(rotation)) throw InputError("cut_photo.rotation_deg must be 0, 90, 180 or 270");
  photo.setup.rotationDegrees = normalizedRotation(static_cast<int>(rotation));
  const json mirror = in.value("mirror", json(false));
  if (!mirror.is_boolean()) throw InputError("cut_photo.mirror must be true or false");
  photo.setup.flip = mirror.get<bool>();
  const json plane = in.value("cut_plane", json());
  if (!plane.is_object()) throw InputError("cut_photo.cut_plane must be an object");
  photo.plane.offsetMm = readJsonNumber(plane.value("offset_mm", json(0.0)), "cut_photo.cut_plane.offset_mm");
  photo.plane.azimuthDeg =
      readJsonNumber(plane.value("azimuth_deg", json(0.0)), "cut_photo.cut_plane.azimuth_deg");
  photo.plane.elevationDeg =
      readJsonNumber(plane.value("elevation_deg", json(0.0)), "cut_photo.cut_plane.elevation_deg");
  return photo;
}

}  // namespace kerf
