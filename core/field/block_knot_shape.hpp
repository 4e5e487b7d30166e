#pragma once
// A block's knot (field/block_knots.hpp) in a woodworker's words, for the editor's table of the block's
// knots (docs/editor.md, "Knots in the block"): where the branch leaves the pith, at what angle to it and
// which way around it, how fast it thickens, whether and when it died; and, read from the growth field,
// where its axis comes out of the block and how thick the knot is there. Edits go back to the knot itself:
// only what was changed moves (a knot whose origin lies off the pith keeps its offset).
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "geometry/block.hpp"

namespace kerf {

struct BlockKnotShape {
  float heightMm = 0.0f;  // where it leaves the pith: mm along the pith from the level of the block's centre
  float angleToPithDeg = 90.0f;  // between the branch and the pith: 90 straight out, less: rising with it
  float aroundDeg = 0.0f;        // which way around the pith, from PithAxis::reference towards its binormal
  float speed = 0.16f;           // BlockKnot::speed: knot radius per mm of the stem's radius
  float taper = 0.0f;            // BlockKnot::taper
  float deathYears = std::numeric_limits<float>::infinity();  // BlockKnot::deathTime; infinity: alive

  bool operator==(const BlockKnotShape&) const = default;
};

BlockKnotShape describeBlockKnot(const BlockKnot& knot, const PithAxis& pith);
// `knot` with `shape`: the origin moves along the pith when the height changed, the direction turns when
// the angle or the way around changed; speed, taper and death are copied.
BlockKnot reshapeBlockKnot(BlockKnot knot, const BlockKnotShape& shape, const PithAxis& pith);

// Where the knot's axis crosses the block's surface (at most twice: in and out; once when it starts
// inside the block), with the stem time there and the knot's diameter across its axis (its section at
// that time, or at its death: T_k < G, ignoring the smoothing of the union).
struct KnotCrossing {
  FaceId face = FaceId::A;
  glm::vec3 point{0.0f};   // block mm
  float stemYears = 0.0f;  // G at the point
  float diameterMm = 0.0f;
};
std::vector<KnotCrossing> knotCrossings(const BlockKnot& knot, const Block& block, const GrowthField& field,
                                        const KnotSettings& settings);
// A death for a knot that is made dead (the table's Dead box): the stem time half way along its run
// through the block (at the block's centre when its axis misses the block), at least one year.
float middleStemYears(const BlockKnot& knot, const Block& block, const GrowthField& field);

}  // namespace kerf
