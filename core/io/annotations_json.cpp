#include "io/annotations_json.hpp"

#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "io/json_file.hpp"
#include "util/error.hpp"
#include "util/parse_number.hpp"

namespace kerf {
using nlohmann::json;

namespace {

constexpr float kOutsideToleranceMm = 1.0f;

std::string faceName(FaceId face) {
  return std::string(1, faceLetter(face));
}

FaceId readFace(const json& value, const std::string& what) {
  if (!value.is_string() || value.get<std::string>().size() != 1)
    throw InputError(what + " must be a face letter \"A\"..\"F\", got " + describeJson(value));
  const auto face = faceFromLetter(value.get<std::string>()[0]);
  if (!face) throw InputError(what + " must be a face letter \"A\"..\"F\", got " + describeJson(value));
  return *face;
}

std::string number(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

glm::vec2 readPoint(const json& value, const std::string& what, const Block& block, FaceId face) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
    throw InputError(what + " must be [u, v] in mm, got " + describeJson(value));
  const glm::vec2 p(checkedNumber<float>(value[0].get<double>(), what),
                    checkedNumber<float>(value[1].get<double>(), what));
  // Points a little outside are kept (the block may have been resized after tracing); points far
  // outside (e.g. pixels written where mm are expected) are refused.
  const glm::vec2 size = faceSizeMm(block, face);
  const glm::vec2 slack = glm::max(glm::vec2(kOutsideToleranceMm), size);
  if (p.x < -slack.x || p.y < -slack.y || p.x > size.x + slack.x || p.y > size.y + slack.y) {
    throw InputError(what + " = " + value.dump() + " lies far outside face " + faceName(face) + " (" +
                     number(size.x) + " x " + number(size.y) + " mm): points are in mm on the face");
  }
  return p;
}

}  // namespace

json annotationsToJson(const Annotations& annotations) {
  json traces = json::array();
  for (const RingTrace& trace : annotations.traces) {
    json points = json::array();
    for (glm::vec2 p : trace.points) points.push_back({p.x, p.y});
    json t = {{"face", faceName(trace.face)},
              {"points", std::move(points)},
              {"origin", trace.origin == TraceOrigin::Detected ? "detected" : "drawn"}};
    if (trace.year) t["year"] = *trace.year;
    traces.push_back(std::move(t));
  }
  json knots = json::array();
  for (const KnotMark& mark : annotations.knots) {
    json k = {{"knot", mark.knot}, {"face", faceName(mark.face)}, {"point", {mark.point.x, mark.point.y}}};
    if (mark.accuracyMm != kDefaultKnotMarkAccuracyMm) k["accuracy_mm"] = mark.accuracyMm;
    if (mark.released) k["released"] = true;
    if (mark.ignoreEdge) k["ignore_edge"] = true;
    knots.push_back(std::move(k));
  }
  return {{"units", "face_mm"}, {"traces", std::move(traces)}, {"knots", std::move(knots)}};
}

Annotations annotationsFromJson(const json& in, const Block& block) {
  if (!in.is_object()) throw InputError("\"annotations\" must be an object with \"traces\" and \"knots\"");
  if (in.contains("units") && in["units"] != "face_mm")
    throw InputError("annotations.units must be \"face_mm\", got " + describeJson(in["units"]));
  for (const auto& [key, value] : in.items())
    if (key != "units" && key != "traces" && key != "knots")
      throw InputError("unknown key annotations." + key + " (expected traces, knots, units)");
  Annotations out;
  if (in.contains("traces")) {
    const json& traces = in["traces"];
    if (!traces.is_array()) throw InputError("annotations.traces must be a list");
    for (std::size_t i = 0; i < traces.size(); ++i) {
      const std::string what = "annotations.traces[" + std::to_string(i) + "]";
      const json& t = traces[i];
      if (!t.is_object()) throw InputError(what + " must be an object");
      if (!t.contains("face")) throw InputError(what + " has no \"face\"");
      RingTrace trace;
      trace.face = readFace(t["face"], what + ".face");
      if (!t.contains("points") || !t["points"].is_array())
        throw InputError(what + ".points must be a list of [u, v] points in mm");
      const json& points = t["points"];
      if (points.size() < 2) throw InputError(what + ".points needs at least 2 points");
      for (std::size_t k = 0; k < points.size(); ++k)
        trace.points.push_back(
            readPoint(points[k], what + ".points[" + std::to_string(k) + "]", block, trace.face));
      if (t.contains("year") && !t["year"].is_null()) {
        if (!t["year"].is_number_integer())
          throw InputError(what + ".year must be a whole number, got " + describeJson(t["year"]));
        trace.year = checkedNumber<int>(t["year"].get<double>(), what + ".year");
      }
      if (t.contains("origin")) {
        const json& origin = t["origin"];
        if (origin == "detected")
          trace.origin = TraceOrigin::Detected;
        else if (origin == "drawn")
          trace.origin = TraceOrigin::Drawn;
        else
          throw InputError(what + ".origin must be \"drawn\" or \"detected\", got " + describeJson(origin));
      }
      out.traces.push_back(std::move(trace));
    }
  }
  if (in.contains("knots")) {
    const json& knots = in["knots"];
    if (!knots.is_array()) throw InputError("annotations.knots must be a list");
    for (std::size_t i = 0; i < knots.size(); ++i) {
      const std::string what = "annotations.knots[" + std::to_string(i) + "]";
      const json& k = knots[i];
      if (!k.is_object() || !k.contains("face") || !k.contains("point"))
        throw InputError(what + " must be {\"knot\": id, \"face\": \"A\", \"point\": [u, v]}");
      KnotMark mark;
      if (k.contains("knot")) {
        if (!k["knot"].is_number_integer() || k["knot"].get<double>() < 0)
          throw InputError(what + ".knot must be a whole number >= 0, got " + describeJson(k["knot"]));
        mark.knot = checkedNumber<int>(k["knot"].get<double>(), what + ".knot", 0);
      }
      mark.face = readFace(k["face"], what + ".face");
      mark.point = readPoint(k["point"], what + ".point", block, mark.face);
      if (k.contains("accuracy_mm")) {
        const json& a = k["accuracy_mm"];
        if (!a.is_number() || !(a.get<double>() >= 0.05) || !(a.get<double>() <= 50.0))
          throw InputError(what + ".accuracy_mm must be a number of mm from 0.05 to 50, got " +
                           describeJson(a));
        mark.accuracyMm = static_cast<float>(a.get<double>());
      }
      if (k.contains("released")) {
        if (!k["released"].is_boolean())
          throw InputError(what + ".released must be true or false, got " + describeJson(k["released"]));
        mark.released = k["released"].get<bool>();
      }
      if (k.contains("ignore_edge")) {
        if (!k["ignore_edge"].is_boolean())
          throw InputError(what + ".ignore_edge must be true or false, got " +
                           describeJson(k["ignore_edge"]));
        mark.ignoreEdge = k["ignore_edge"].get<bool>();
      }
      out.knots.push_back(mark);
    }
  }
  return out;
}

}  // namespace kerf
