#pragma once
// A knot described by a few numbers a user can edit (the editor's knot table), and back to the sampled
// skeleton of Table 2 (field/log_model.hpp). The course is the random logs' form:
//   z(d) = height + bend sqrt(d) + rise d,   omega(d) = azimuth + twist log(1 + d) / log(1 + length)
// A measured knot is described by the least-squares fit of that form; the edited knot is sampled again
// from it (same distance step), so editing a CT knot smooths its course.
#include <limits>

#include "field/log_model.hpp"

namespace kerf {

struct KnotShape {
  float heightMm = 0.0f;    // where the branch leaves the pith, up the log
  float azimuthRad = 0.0f;  // direction around the stem at the pith (from +x towards +y)
  float rise = 0.3f;        // mm the branch climbs per mm outward, far from the pith
  float bend = 1.0f;        // early upward bend near the pith, mm per sqrt(mm) (0: straight)
  float twistRad = 0.0f;    // change of azimuth from the pith to the branch's end
  float lengthMm = 150.0f;  // how far out the skeleton is sampled
  float deathDistanceMm = std::numeric_limits<float>::infinity();  // inf: never died
};

KnotShape describeKnot(const Knot& knot);
// Samples the shape every `distanceStep` mm (at least 2 samples); `endDistance` is where the branch broke
// off (kept from the knot being edited).
Knot makeKnot(const KnotShape& shape, float distanceStep = 4.0f,
              float endDistance = std::numeric_limits<float>::infinity());

}  // namespace kerf
