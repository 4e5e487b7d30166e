// Ring traces and knot marks: coordinates, the pure edits (split, join, smooth, renumber), detected
// contours taken over as traces, and the Mokume annotation images (write -> read round trip).
#include <gtest/gtest.h>

#include "test_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <numbers>

#include "io/annotations_json.hpp"
#include "io/image.hpp"
#include "io/mokume_annotation_files.hpp"
#include "rings/annotations.hpp"
#include "rings/contours.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

RingTrace line(std::vector<glm::vec2> points, FaceId face = FaceId::A, std::optional<int> year = std::nullopt,
               TraceOrigin origin = TraceOrigin::Drawn) {
  return {face, std::move(points), year, origin};
}

// The largest distance from any point of `a` (sampled every 0.02 mm) to the polyline `b`.
float oneSidedDistance(const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b) {
  float worst = 0;
  for (glm::vec2 p : resamplePolyline(a, 0.02f)) worst = std::max(worst, nearestOnPolyline(b, p)->distance);
  return worst;
}

float hausdorff(const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b) {
  return std::max(oneSidedDistance(a, b), oneSidedDistance(b, a));
}

std::vector<glm::vec2> arc(glm::vec2 centre, float radius, float from, float to, int n) {
  std::vector<glm::vec2> out;
  for (int i = 0; i < n; ++i) {
    const float a = from + (to - from) * i / (n - 1);
    out.push_back(centre + radius * glm::vec2(std::cos(a), std::sin(a)));
  }
  return out;
}

fs::path scratch(const std::string& name) {
  return kerf::testing::scratchFolder("annotations", name);
}

}  // namespace

TEST(Annotations, FaceMillimetresMatchTheFaceImageTable) {
  const Block block(glm::vec3(40, 60, 20));
  for (FaceId face : kAllFaces) {
    const glm::vec2 size = faceSizeMm(block, face);
    const glm::ivec2 image(400, 300);
    for (glm::vec2 q : {glm::vec2(0, 0), glm::vec2(size.x, size.y), glm::vec2(3.5f, 7.25f)}) {
      const glm::vec2 pixel = faceMmToImage(block, face, q, image);
      EXPECT_LT(glm::length(faceMmToBlock(block, face, q) - block.imageToBlock(face, pixel, image)), 1e-4f);
      EXPECT_LT(glm::length(blockToFaceMm(block, face, faceMmToBlock(block, face, q)) - q), 1e-4f);
      EXPECT_LT(glm::length(imageToFaceMm(block, face, pixel, image) - q), 1e-4f);
    }
  }
  // Face A's top-left corner is at (-x, +y, +z) (image right = +x, down = -y).
  EXPECT_LT(glm::length(faceMmToBlock(block, FaceId::A, {0, 0}) - glm::vec3(-20, 30, 10)), 1e-5f);
}

TEST(Annotations, SplitCutsAtTheNearestPointAndKeepsYearAndOrigin) {
  const RingTrace trace = line({{0, 0}, {10, 0}}, FaceId::C, 4, TraceOrigin::Detected);
  const auto pieces = splitTrace(trace, {4, 1});
  ASSERT_TRUE(pieces);
  EXPECT_EQ(pieces->first.points, (std::vector<glm::vec2>{{0, 0}, {4, 0}}));
  EXPECT_EQ(pieces->second.points, (std::vector<glm::vec2>{{4, 0}, {10, 0}}));
  EXPECT_EQ(pieces->first.year, 4);
  EXPECT_EQ(pieces->second.origin, TraceOrigin::Detected);
  EXPECT_EQ(pieces->second.face, FaceId::C);

  // At a vertex: the vertex is shared, not doubled.
  const auto atVertex = splitTrace(line({{0, 0}, {5, 0}, {5, 5}}), {5.2f, -0.1f});
  ASSERT_TRUE(atVertex);
  EXPECT_EQ(atVertex->first.points, (std::vector<glm::vec2>{{0, 0}, {5, 0}}));
  EXPECT_EQ(atVertex->second.points, (std::vector<glm::vec2>{{5, 0}, {5, 5}}));

  // At an end nothing would be left on one side.
  EXPECT_FALSE(splitTrace(trace, {-1, 0}));
  EXPECT_FALSE(splitTrace(trace, {10.01f, 0.5f}));
  EXPECT_FALSE(splitTrace(line({{1, 1}}), {1, 1}));

  Annotations a;
  a.traces = {trace, line({{0, 5}, {10, 5}})};
  const Annotations split = splitTraceAt(a, 0, {7, 0});
  ASSERT_EQ(split.traces.size(), 3u);
  EXPECT_EQ(split.traces[0].points.back(), glm::vec2(7, 0));
  EXPECT_EQ(split.traces[2].points.front(), glm::vec2(7, 0));
  EXPECT_EQ(splitTraceAt(a, 5, {7, 0}), a);  // no such trace
}

TEST(Annotations, JoinConnectsTheNearestEnds) {
  const RingTrace a = line({{0, 0}, {5, 0}});
  const RingTrace b = line({{10, 0}, {6, 0}}, FaceId::A, 7);
  const auto ab = joinTraces(a, b);
  ASSERT_TRUE(ab);
  EXPECT_EQ(ab->points, (std::vector<glm::vec2>{{0, 0}, {5, 0}, {6, 0}, {10, 0}}));
  EXPECT_EQ(ab->year, 7);  // a has none
  EXPECT_EQ(ab->origin, TraceOrigin::Drawn);

  // b lies before a's start: b comes first, a keeps its direction.
  const auto ba = joinTraces(line({{5, 0}, {9, 0}}), line({{0, 0}, {4, 0}}));
  ASSERT_TRUE(ba);
  EXPECT_EQ(ba->points, (std::vector<glm::vec2>{{0, 0}, {4, 0}, {5, 0}, {9, 0}}));
  // Touching ends are not doubled.
  EXPECT_EQ(joinTraces(line({{0, 0}, {1, 0}}), line({{1, 0}, {2, 0}}))->points.size(), 3u);
  // Different faces do not join.
  EXPECT_FALSE(joinTraces(a, line({{6, 0}, {9, 0}}, FaceId::B)));

  // Several pieces, in any order and direction, into one.
  Annotations set;
  set.traces = {line({{4, 0}, {6, 0}}), line({{0, 5}, {9, 5}}), line({{9, 0}, {7, 0}}),
                line({{0, 0}, {3, 0}})};
  const Annotations joined = joinTracesAt(set, {0, 2, 3});
  ASSERT_EQ(joined.traces.size(), 2u);
  EXPECT_EQ(joined.traces[0].points,
            (std::vector<glm::vec2>{{0, 0}, {3, 0}, {4, 0}, {6, 0}, {7, 0}, {9, 0}}));
  EXPECT_EQ(joined.traces[1].points, set.traces[1].points);
  EXPECT_EQ(joinTracesAt(set, {0}), set);
}

TEST(Annotations, ResampleGivesEqualSpacing) {
  const std::vector<glm::vec2> l{{0, 0}, {3, 0}, {3, 4}};  // 7 mm long
  const auto even = resamplePolyline(l, 0.5f);
  ASSERT_EQ(even.size(), 15u);
  EXPECT_EQ(even.front(), l.front());
  EXPECT_EQ(even.back(), l.back());
  for (std::size_t i = 1; i < even.size(); ++i) {
    // Across the corner the chord is shorter than the arc length.
    const float gap = glm::length(even[i] - even[i - 1]);
    EXPECT_LE(gap, 0.5f + 1e-4f);
    EXPECT_GE(gap, 0.35f);
  }
}

TEST(Annotations, SmoothingKeepsStraightStrokesAndRemovesJitter) {
  // A straight stroke with unevenly spaced points stays on its line, ends in place.
  const std::vector<glm::vec2> straight{{1, 1}, {1.3f, 1.6f}, {2, 3}, {4.5f, 8}};
  const auto s = smoothPolyline(straight, 0.25f, 0.6f);
  EXPECT_EQ(s.front(), straight.front());
  EXPECT_EQ(s.back(), straight.back());
  for (glm::vec2 p : s) EXPECT_LT(std::abs(2 * p.x - p.y - 1), 1e-4f);

  // A hand-drawn arc of radius 10 mm with 0.2 mm jitter every 0.3 mm: after smoothing the points lie
  // within 0.05 mm of the circle (the Gaussian shrinks a curve by about sigma^2 / 2R = 0.018 mm).
  const glm::vec2 centre(-5, 20);
  std::vector<glm::vec2> jittery;
  const int n = 60;
  for (int i = 0; i < n; ++i) {
    const float a = -1.2f + 0.9f * i / (n - 1);
    const float r = 10 + (i % 2 ? 0.2f : -0.2f);
    jittery.push_back(centre + r * glm::vec2(std::cos(a), std::sin(a)));
  }
  const auto smooth = smoothPolyline(jittery, 0.25f, 0.6f);
  float worst = 0;
  for (std::size_t i = 2; i + 2 < smooth.size(); ++i)
    worst = std::max(worst, std::abs(glm::length(smooth[i] - centre) - 10.0f));
  EXPECT_LT(worst, 0.05f);
  float raw = 0;
  for (glm::vec2 p : jittery) raw = std::max(raw, std::abs(glm::length(p - centre) - 10.0f));
  EXPECT_GT(raw, 0.19f);
  EXPECT_EQ(smoothPolyline({{1, 1}}), (std::vector<glm::vec2>{{1, 1}}));
}

TEST(Annotations, SimplifyDropsOnlyPointsWithinTolerance) {
  const std::vector<glm::vec2> l{{0, 0}, {1, 0.01f}, {2, 0}, {3, 1}};
  EXPECT_EQ(simplifyPolyline(l, 0.05f), (std::vector<glm::vec2>{{0, 0}, {2, 0}, {3, 1}}));
  EXPECT_EQ(simplifyPolyline(l, 0.001f), l);
}

TEST(Annotations, NumberingAndRenumberingAGroup) {
  Annotations a;
  a.traces = {line({{0, 0}, {1, 0}}, FaceId::A, std::nullopt, TraceOrigin::Detected),
              line({{0, 1}, {1, 1}}, FaceId::A, 3), line({{0, 2}, {1, 2}})};
  const Annotations numbered = setYears(a, {0, 2, 9}, 5);
  EXPECT_EQ(numbered.traces[0].year, 5);
  EXPECT_EQ(numbered.traces[0].origin, TraceOrigin::Drawn);  // the user's now: re-detection keeps it
  EXPECT_EQ(numbered.traces[1].year, 3);
  EXPECT_EQ(numbered.traces[2].year, 5);
  const Annotations shifted = offsetYears(numbered, {0, 1}, -2);
  EXPECT_EQ(shifted.traces[0].year, 3);
  EXPECT_EQ(shifted.traces[1].year, 1);
  EXPECT_EQ(shifted.traces[2].year, 5);
  EXPECT_EQ(offsetYears(a, {0}, 4).traces[0].year, std::nullopt);  // unnumbered stays unnumbered
  EXPECT_EQ(setYears(numbered, {1}, std::nullopt).traces[1].year, std::nullopt);
  EXPECT_EQ(removeTraces(a, {2, 0, 0}).traces, std::vector<RingTrace>{a.traces[1]});
}

TEST(Annotations, DetectedContoursBecomeDetectedTracesAndReplaceOnlyDetected) {
  const Block block;  // 40 mm cube
  FaceContour contour;
  contour.face = FaceId::B;
  for (int x = 10; x <= 50; ++x) contour.pixels.emplace_back(x, 20);
  const auto traces = tracesFromContours({contour}, block, {256, 256});
  ASSERT_EQ(traces.size(), 1u);
  EXPECT_EQ(traces[0].face, FaceId::B);
  EXPECT_EQ(traces[0].origin, TraceOrigin::Detected);
  ASSERT_EQ(traces[0].points.size(), 2u);  // a straight run simplifies to its ends
  const float mmPerPx = 40.0f / 256;
  EXPECT_NEAR(traces[0].points[0].x, 10.5f * mmPerPx, 1e-5f);
  EXPECT_NEAR(traces[0].points[0].y, 20.5f * mmPerPx, 1e-5f);
  EXPECT_NEAR(traces[0].points[1].x, 50.5f * mmPerPx, 1e-5f);

  Annotations a;
  a.traces = {line({{0, 0}, {1, 0}}, FaceId::A, std::nullopt, TraceOrigin::Detected),
              line({{0, 1}, {1, 1}}, FaceId::A, 3)};
  a.knots = {{0, FaceId::C, {1, 2}}};
  const Annotations replaced = replaceDetectedTraces(a, traces);
  ASSERT_EQ(replaced.traces.size(), 2u);
  EXPECT_EQ(replaced.traces[0], a.traces[1]);
  EXPECT_EQ(replaced.traces[1], traces[0]);
  EXPECT_EQ(replaced.knots, a.knots);
}

TEST(Annotations, MokumeRingImageRoundTripKeepsTracesAndYears) {
  const Block block;
  const glm::ivec2 size(256, 256);
  const float px = 40.0f / 256;
  // Rings of a pith beyond the bottom-left corner (3 mm apart), a straight trace, and an unnumbered one.
  Annotations a;
  for (int k = 0; k < 3; ++k)
    a.traces.push_back(line(arc({-6, 44}, 20.0f + 3.0f * k, -1.2f, -0.25f, 25), FaceId::B, 3 + k));
  a.traces.push_back(line({{30, 5}, {36, 30}}, FaceId::B, 9));
  a.traces.push_back(line({{2, 2}, {10, 3}}, FaceId::B));
  a.traces.push_back(line({{5, 5}, {30, 8}}, FaceId::E, 1));

  const GrayImage8 image = ringImageFromTraces(a, FaceId::B, block, size);
  ASSERT_EQ(image.width, 256);
  int background = 0;
  for (unsigned char v : image.pixels) background += v == 255;
  EXPECT_GT(background, 256 * 256 - 3000);
  EXPECT_EQ(image.at(static_cast<int>(2.0f / px), static_cast<int>(2.0f / px)),
            255);  // unnumbered: not drawn

  const auto read = ringTracesFromImage(image, FaceId::B, block);
  for (std::size_t i = 0; i < 4; ++i) {
    const RingTrace& original = a.traces[i];
    std::vector<const RingTrace*> same;
    for (const RingTrace& t : read)
      if (t.year == original.year) same.push_back(&t);
    ASSERT_EQ(same.size(), 1u) << "year " << *original.year;
    EXPECT_EQ(same[0]->face, FaceId::B);
    // Within a pixel of each other, both ways.
    EXPECT_LT(hausdorff(original.points, same[0]->points), 1.0f * px) << "year " << *original.year;
  }
  EXPECT_EQ(read.size(), 4u);

  // Through files, as a sample folder: the same traces and years, and face E's trace.
  const fs::path dir = scratch("round_trip");
  std::array<glm::ivec2, 6> sizes;
  sizes.fill(size);
  const auto written = writeMokumeAnnotations(a, block, dir, sizes);
  EXPECT_EQ(written.size(), 2u);  // B_ann.png, E_ann.png
  EXPECT_TRUE(fs::exists(dir / "B_ann.png"));
  const MokumeAnnotationFiles files = findMokumeAnnotationFiles(dir);
  EXPECT_FALSE(files.rings[faceIndex(FaceId::B)].empty());
  EXPECT_TRUE(files.rings[faceIndex(FaceId::A)].empty());
  const Annotations back = readMokumeAnnotations(files, block);
  ASSERT_EQ(back.traces.size(), 5u);
  for (const RingTrace& t : back.traces) {
    ASSERT_TRUE(t.year);
    const auto original = std::find_if(a.traces.begin(), a.traces.end(), [&](const RingTrace& o) {
      return o.year == t.year && o.face == t.face;
    });
    ASSERT_NE(original, a.traces.end());
    EXPECT_LT(hausdorff(original->points, t.points), 1.0f * px);
  }
}

TEST(Annotations, MokumeImageAtTheFaceSizeOfACuboid) {
  const Block block(glm::vec3(40, 60, 20));
  Annotations a;
  a.traces.push_back(line({{2, 2}, {38, 57}}, FaceId::A, 12));
  const glm::ivec2 size(200, 300);  // 5 px/mm
  const auto read = ringTracesFromImage(ringImageFromTraces(a, FaceId::A, block, size), FaceId::A, block);
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].year, 12);
  EXPECT_LT(hausdorff(a.traces[0].points, read[0].points), 0.2f);
}

TEST(Annotations, KnotMarksAreTheGreyBlobsOfAKnotImage) {
  const Block block;
  GrayImage8 image;
  image.width = image.height = 64;
  image.pixels.assign(64 * 64, 0);
  const auto set = [&](int x, int y, unsigned char v) { image.pixels[y * 64 + x] = v; };
  for (int y = 9; y <= 11; ++y)
    for (int x = 19; x <= 21; ++x) set(x, y, 200);  // centre pixel (20, 10)
  set(40, 50, 180);
  set(41, 50, 220);  // centre between pixels 40 and 41
  set(5, 5, 100);    // not in 180..220
  set(6, 60, 230);
  const auto marks = knotMarksFromImage(image, FaceId::C, block);
  ASSERT_EQ(marks.size(), 2u);
  const float mm = 40.0f / 64;
  EXPECT_EQ(marks[0].face, FaceId::C);
  EXPECT_NEAR(marks[0].point.x, 20.5f * mm, 1e-4f);
  EXPECT_NEAR(marks[0].point.y, 10.5f * mm, 1e-4f);
  EXPECT_NEAR(marks[1].point.x, 41.0f * mm, 1e-4f);
  EXPECT_NEAR(marks[1].point.y, 50.5f * mm, 1e-4f);

  // A knot through faces C and F, written and read as a sample folder: one knot, two marks.
  Annotations a;
  a.knots = {{0, FaceId::C, {12.0f, 30.0f}}, {0, FaceId::F, {25.0f, 8.0f}}};
  const fs::path dir = scratch("knots");
  std::array<glm::ivec2, 6> sizes;
  sizes.fill({256, 256});
  writeMokumeAnnotations(a, block, dir, sizes);
  EXPECT_TRUE(fs::exists(dir / "C_knot.png"));
  EXPECT_TRUE(fs::exists(dir / "F_knot.png"));
  const Annotations back = readMokumeAnnotations(findMokumeAnnotationFiles(dir), block);
  ASSERT_EQ(back.knots.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(back.knots[i].knot, 0);
    EXPECT_EQ(back.knots[i].face, a.knots[i].face);
    EXPECT_LT(glm::length(back.knots[i].point - a.knots[i].point),
              0.75f * 40.0f / 256);  // drawn at a whole pixel
  }
  EXPECT_EQ(back.nextKnotId(), 1);
}

TEST(Annotations, UnreadableAnnotationImageNamesTheFile) {
  const fs::path dir = scratch("unreadable");
  std::ofstream(dir / "B_ann.png") << "not a png";
  try {
    readMokumeAnnotations(findMokumeAnnotationFiles(dir), Block());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("B_ann.png"), std::string::npos) << e.what();
  }
}

TEST(Annotations, KnotMarkAccuracyReleaseAndIgnoredEdgeRoundTripThroughJson) {
  const Block block;
  Annotations a;
  a.knots = {{3, FaceId::C, {12.0f, 30.0f}}, {3, FaceId::F, {25.0f, 8.0f}, 2.5f, true, true}};
  const nlohmann::json json = annotationsToJson(a);
  // Defaults are not written, so files without these keys stay as they were.
  EXPECT_FALSE(json["knots"][0].contains("accuracy_mm"));
  EXPECT_FALSE(json["knots"][0].contains("released"));
  EXPECT_EQ(json["knots"][1]["accuracy_mm"], 2.5);
  EXPECT_EQ(json["knots"][1]["released"], true);
  EXPECT_FALSE(json["knots"][0].contains("ignore_edge"));
  EXPECT_EQ(json["knots"][1]["ignore_edge"], true);
  EXPECT_EQ(annotationsFromJson(json, block).knots, a.knots);

  for (const auto& [key, value] :
       std::vector<std::pair<std::string, nlohmann::json>>{{"accuracy_mm", 0.0},
                                                           {"accuracy_mm", -1.0},
                                                           {"accuracy_mm", 80.0},
                                                           {"accuracy_mm", "1"},
                                                           {"released", 1},
                                                           {"ignore_edge", "yes"}}) {
    nlohmann::json bad = json;
    bad["knots"][0][key] = value;
    try {
      annotationsFromJson(bad, block);
      ADD_FAILURE() << key << " = " << value.dump() << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("annotations.knots[0]." + key), std::string::npos) << e.what();
    }
  }
}
