// A log and its board in a project (core/io/project_log.hpp) and editable knot shapes
// (core/field/knot_shape.hpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "field/knot_shape.hpp"
#include "io/project.hpp"
#include "util/error.hpp"

using namespace kerf;

TEST(ProjectLog, RoundTripsThroughTheProjectFile) {
  Project project;
  ProjectLog log{generateRandomLog({5}), {}};
  log.board.center = {12.5f, -30.25f, 700.0f};
  log.board.size = {110.0f, 200.0f, 25.0f};
  log.board.rotationDeg = {1.0f, 33.0f, -2.5f};
  project.log = log;
  const nlohmann::json json = projectToJson(project, "/tmp");
  ASSERT_TRUE(json.contains("log"));
  const Project back = projectFromJson(nlohmann::json::parse(json.dump()), "/tmp");
  ASSERT_TRUE(back.log.has_value());
  EXPECT_EQ(back.log->board.center, log.board.center);
  EXPECT_EQ(back.log->board.size, log.board.size);
  EXPECT_EQ(back.log->board.rotationDeg, log.board.rotationDeg);
  ASSERT_EQ(back.log->log.knots.size(), log.log.knots.size());
  for (std::size_t k = 0; k < log.log.knots.size(); ++k) {
    EXPECT_EQ(back.log->log.knots[k].heights, log.log.knots[k].heights);
    EXPECT_EQ(back.log->log.knots[k].azimuths, log.log.knots[k].azimuths);
    EXPECT_EQ(back.log->log.knots[k].deathDistance, log.log.knots[k].deathDistance);
  }
  EXPECT_EQ(back.log->log.stem.radii, log.log.stem.radii);
}

TEST(ProjectLog, ProjectsWithoutALogStayWithout) {
  const nlohmann::json json = projectToJson(Project(), "/tmp");
  EXPECT_FALSE(json.contains("log"));
  EXPECT_FALSE(projectFromJson(json, "/tmp").log.has_value());
}

TEST(ProjectLog, RefusesABadBoard) {
  Project project;
  project.log = ProjectLog{generateRandomLog({5}), {}};
  nlohmann::json json = projectToJson(project, "/tmp");
  json["log"]["board"]["size_mm"] = {110.0, -1.0, 20.0};
  EXPECT_THROW(projectFromJson(json, "/tmp"), InputError);
  json["log"]["board"].erase("size_mm");
  EXPECT_THROW(projectFromJson(json, "/tmp"), InputError);
}

TEST(KnotShape, DescribesTheKnotsItMakesExactly) {
  KnotShape shape;
  shape.heightMm = 812.0f;
  shape.azimuthRad = 2.0f;
  shape.rise = 0.42f;
  shape.bend = 1.7f;
  shape.twistRad = -0.3f;
  shape.lengthMm = 148.0f;
  shape.deathDistanceMm = 55.0f;
  const Knot knot = makeKnot(shape, 4.0f);
  EXPECT_EQ(knot.samples(), 38);  // 0, 4, .. 148 mm
  EXPECT_FLOAT_EQ(knot.maxDistance(), 148.0f);
  EXPECT_FLOAT_EQ(knot.heightAt(100.0f), 812.0f + 1.7f * 10.0f + 42.0f);
  const KnotShape back = describeKnot(knot);
  EXPECT_NEAR(back.heightMm, shape.heightMm, 1e-4f);
  EXPECT_NEAR(back.azimuthRad, shape.azimuthRad, 1e-6f);
  EXPECT_NEAR(back.rise, shape.rise, 1e-4f);
  EXPECT_NEAR(back.bend, shape.bend, 1e-3f);
  EXPECT_NEAR(back.twistRad, shape.twistRad, 1e-5f);
  EXPECT_FLOAT_EQ(back.lengthMm, shape.lengthMm);
  EXPECT_EQ(back.deathDistanceMm, 55.0f);
}

TEST(KnotShape, FitsMeasuredKnotsClosely) {
  // Random logs' knots follow the same form (z0 + a sqrt(d) + b d): their description reproduces them.
  const LogModel log = generateRandomLog({9});
  for (const Knot& knot : log.knots) {
    const Knot again = makeKnot(describeKnot(knot), knot.distanceStep, knot.endDistance);
    ASSERT_EQ(again.samples(), knot.samples());
    for (int j = 0; j < knot.samples(); ++j) EXPECT_NEAR(again.heights[j], knot.heights[j], 0.02f);
  }
}
