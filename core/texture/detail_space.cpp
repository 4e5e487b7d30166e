#include "texture/detail_space.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "util/error.hpp"

namespace kerf {
namespace {

constexpr const char* kRayLightness = "rays.lightness";
constexpr const char* kLatewoodContrast = "color.latewood_contrast";

// The two coordinates that are not schema parameters (detail_space.hpp), searched after the schema's.
const DetailCoordinate kDerived[] = {
    {kRayLightness, false, 0.6f, 1.4f},
    {kLatewoodContrast, true, 0.5f, 1.1f},
};

float& scalar(WoodParameters& params, const std::string& id) {
  const auto index = parameterIndex(id);
  if (!index) throw InputError("unknown detail parameter: " + id);
  return params.components(*index)[0];
}

float luminanceOf(glm::vec3 c) {
  return 0.299f * c.x + 0.587f * c.y + 0.114f * c.z;
}

}  // namespace

std::vector<DetailCoordinate> allDetailCoordinates() {
  std::vector<DetailCoordinate> out;
  for (const ParamSpec& spec : parameterSchema()) {
    if (!spec.search.searched) continue;
    out.push_back(
        {std::string(spec.id), spec.search.scale == ParamScale::Log, spec.search.lo, spec.search.hi});
  }
  out.insert(out.end(), std::begin(kDerived), std::end(kDerived));
  return out;
}

std::vector<DetailCoordinate> detailCoordinates(const std::vector<std::string>& ids) {
  const std::vector<DetailCoordinate> all = allDetailCoordinates();
  if (ids.empty()) return all;
  std::vector<DetailCoordinate> out;
  for (const std::string& id : ids) {
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const DetailCoordinate& c) { return c.id == id; });
    if (it == all.end()) throw InputError("not a detail parameter the texture inference searches: " + id);
    out.push_back(*it);
  }
  return out;
}

float detailValue(const WoodParameters& params, const DetailCoordinate& coordinate) {
  if (coordinate.id == kLatewoodContrast) return 1.0f;  // a multiplier of the parameters it is applied to
  if (coordinate.id == kRayLightness)
    return luminanceOf(params.rayColor) / std::max(1e-3f, luminanceOf(params.earlywoodColor));
  const auto index = parameterIndex(coordinate.id);
  if (!index) throw InputError("unknown detail parameter: " + coordinate.id);
  return params.components(*index)[0];
}

void setDetailValue(WoodParameters& params, const DetailCoordinate& coordinate, float value) {
  if (coordinate.id == kLatewoodContrast) {
    params.latewoodColor = glm::clamp(params.latewoodColor * value, glm::vec3(0.0f), glm::vec3(1.0f));
    params.sapwoodLatewoodColor =
        glm::clamp(params.sapwoodLatewoodColor * value, glm::vec3(0.0f), glm::vec3(1.0f));
    return;
  }
  if (coordinate.id == kRayLightness) {
    params.rayColor = glm::clamp(params.earlywoodColor * value, glm::vec3(0.0f), glm::vec3(1.0f));
    return;
  }
  const ParamSpec* spec = findParameter(coordinate.id);
  scalar(params, coordinate.id) = std::clamp(value, spec->hardMin, spec->hardMax);
}

std::vector<double> encodeDetail(const WoodParameters& params,
                                 const std::vector<DetailCoordinate>& coordinates) {
  std::vector<double> u;
  for (const DetailCoordinate& c : coordinates) {
    const float v = std::clamp(detailValue(params, c), c.lo, c.hi);
    u.push_back(c.logScale ? std::log(v / c.lo) / std::log(c.hi / c.lo) : (v - c.lo) / (c.hi - c.lo));
  }
  return u;
}

WoodParameters decodeDetail(const WoodParameters& base, const std::vector<DetailCoordinate>& coordinates,
                            const std::vector<double>& u) {
  WoodParameters params = base;
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    const DetailCoordinate& c = coordinates[i];
    const double t = std::clamp(u[i], 0.0, 1.0);
    const double v = c.logScale ? c.lo * std::pow(double(c.hi) / c.lo, t) : c.lo + t * (c.hi - c.lo);
    setDetailValue(params, c, static_cast<float>(v));
  }
  return params;
}

void scaleDetailSize(WoodParameters& params, DetailFeature feature, float factor) {
  const auto scale = [&](const char* id) {
    const ParamSpec* spec = findParameter(id);
    float& v = scalar(params, id);
    v = std::clamp(v * factor, spec->hardMin, spec->hardMax);
  };
  switch (feature) {
    case DetailFeature::Fibres:
      for (const char* id : {"fibers.width", "fibers.length"}) scale(id);
      break;
    case DetailFeature::Pores:
      for (const char* id : {"pores.radius_earlywood", "pores.radius_latewood", "pores.cell_size"}) scale(id);
      break;
    case DetailFeature::Rays:
      for (const char* id : {"rays.spacing", "rays.width", "rays.height"}) scale(id);
      break;
  }
}

}  // namespace kerf
