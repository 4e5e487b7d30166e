#pragma once
// The user's annotations of a block's faces: ring traces (hand-drawn, or detected contours taken over
// for editing), optionally numbered by year, and knot marks. They are what a woodworker corrects by
// hand before the growth field is fitted (issue 4; numbered traces as in learned-inference-annual-rings
// Sec. 3.2.3, the Mokume annotation images of Appendix A.1.2).
//
// Coordinates: **face millimetres**. A point (u, v) lies u mm to the right of the face image's left
// edge and v mm below its top edge, in the orientation of the face image (docs/coordinates.md, table
// "Faces A..F"): (0, 0) is the face's top-left corner, (widthMm, heightMm) its bottom-right corner.
// They do not depend on any photo's resolution; faceMmToImage / imageToFaceMm convert to Kerf's
// continuous pixel coordinates of an image covering the face (pixel centres at +0.5), faceMmToBlock to
// block mm.
//
// Everything here is a plain value and a pure function, so the editor's undo commands can store
// Annotations before and after an edit.
#include <array>
#include <cstddef>
#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/block.hpp"
#include "image/gray_image.hpp"

namespace kerf {

struct FaceContour;

// Where a trace came from. Detected traces are replaced when the detector runs again; drawn ones (and
// detected ones the user joined or numbered, which become Drawn) are kept.
enum class TraceOrigin { Detected, Drawn };

// One ring trace: an open polyline on one face, along an annual ring boundary.
struct RingTrace {
  FaceId face = FaceId::A;
  std::vector<glm::vec2> points;  // face mm, in drawing order; at least 2 for a usable trace
  std::optional<int> year;        // relative year number (0..254 in Mokume images); none = unnumbered
  TraceOrigin origin = TraceOrigin::Drawn;

  bool operator==(const RingTrace&) const = default;
};

// Where a knot meets a face. A knot usually crosses the block: it has two marks (where it enters and
// where it leaves), on two faces, sharing the knot id. The fit keeps the knot's axis within accuracyMm of
// each mark (issue 19 item 1) unless the user released the mark, which then only seeds the knot. The
// knot's edge found around a mark on its photo sizes the knot (rings/knot_outline.hpp) unless the user says
// that edge is wrong (ignoreEdge: a resin streak, a shadow or a check beside the knot, as dark as it).
inline constexpr float kDefaultKnotMarkAccuracyMm = 1.0f;
struct KnotMark {
  int knot = 0;  // knot id: marks with the same id are the same knot
  FaceId face = FaceId::A;
  glm::vec2 point{0.0f};  // face mm
  float accuracyMm = kDefaultKnotMarkAccuracyMm;
  bool released = false;
  bool ignoreEdge = false;

  bool operator==(const KnotMark&) const = default;
};

struct Annotations {
  std::vector<RingTrace> traces;
  std::vector<KnotMark> knots;

  bool empty() const { return traces.empty() && knots.empty(); }
  int nextKnotId() const;  // one more than the largest knot id (0 when there is none)
  bool operator==(const Annotations&) const = default;
};

// --- Coordinates ---------------------------------------------------------------------------------

glm::vec2 faceSizeMm(const Block& block, FaceId face);  // (widthMm, heightMm)
glm::vec3 faceMmToBlock(const Block& block, FaceId face, glm::vec2 faceMm);
glm::vec2 blockToFaceMm(const Block& block, FaceId face, glm::vec3 p);  // projected onto the face plane
// Kerf continuous image coordinates (pixel (c, r) has its centre at (c + 0.5, r + 0.5)) of an image of
// imageSize pixels covering the whole face.
glm::vec2 faceMmToImage(const Block& block, FaceId face, glm::vec2 faceMm, glm::ivec2 imageSize);
glm::vec2 imageToFaceMm(const Block& block, FaceId face, glm::vec2 imagePos, glm::ivec2 imageSize);
std::vector<glm::vec3> traceToBlock(const RingTrace& trace, const Block& block);

// --- Geometry of polylines (face mm) --------------------------------------------------------------

struct PolylineHit {
  std::size_t segment = 0;  // the point lies on segment [segment, segment + 1]
  float t = 0.0f;           // 0..1 along that segment
  glm::vec2 point{0.0f};    // the nearest point on the polyline
  float distance = 0.0f;    // from the query point, mm
};
// The nearest point of a polyline (at least 2 points) to `p`; nullopt for fewer than 2 points.
std::optional<PolylineHit> nearestOnPolyline(const std::vector<glm::vec2>& polyline, glm::vec2 p);
float polylineLength(const std::vector<glm::vec2>& polyline);

// Points at equal arc-length spacing (the last gap may be shorter), first and last points kept.
std::vector<glm::vec2> resamplePolyline(const std::vector<glm::vec2>& polyline, float spacingMm);
// Ramer-Douglas-Peucker: drops points closer than toleranceMm to the simplified line; ends kept.
std::vector<glm::vec2> simplifyPolyline(const std::vector<glm::vec2>& polyline, float toleranceMm);
// A freehand stroke made smooth: resampled at spacingMm, then a Gaussian average along the arc length
// (sigmaMm) with the end points held where they were, then resampled again. A straight stroke stays
// straight; hand jitter shorter than about sigma is removed. Fewer than 2 points are returned as they are.
std::vector<glm::vec2> smoothPolyline(const std::vector<glm::vec2>& polyline, float spacingMm = 0.25f,
                                      float sigmaMm = 0.6f);

// --- Edits (pure; each returns the new value, the input is unchanged) ------------------------------

// Splits the trace at the point of it nearest to `at`: two traces sharing that point, with the year
// and origin of the original. nullopt when the split point is (within minPieceMm) an end of the trace,
// so that one piece would be empty.
std::optional<std::pair<RingTrace, RingTrace>> splitTrace(const RingTrace& trace, glm::vec2 at,
                                                          float minPieceMm = 0.05f);
// Joins two traces of the same face into one through their nearest ends (the result starts at the far
// end of `a`). The year is a's, else b's; the result is Drawn. nullopt when the faces differ or a trace
// has no points.
std::optional<RingTrace> joinTraces(const RingTrace& a, const RingTrace& b);

// On a whole set (indices into annotations.traces; out-of-range indices are ignored):
Annotations removeTraces(const Annotations& annotations, const std::vector<std::size_t>& indices);
// Replaces trace `index` by its two pieces (the second is appended at the end); unchanged when the
// split is not possible.
Annotations splitTraceAt(const Annotations& annotations, std::size_t index, glm::vec2 at);
// Joins the traces in `indices` (all on one face) into one, greedily through nearest ends; the joined
// trace takes the place of the first index. Unchanged when fewer than 2 or on different faces.
Annotations joinTracesAt(const Annotations& annotations, const std::vector<std::size_t>& indices);
// Sets the year of the traces (nullopt: unnumbered). Numbered traces become Drawn.
Annotations setYears(const Annotations& annotations, const std::vector<std::size_t>& indices,
                     std::optional<int> year);
// Adds `offset` to the years of the numbered traces among `indices` (renumbering a group at once).
Annotations offsetYears(const Annotations& annotations, const std::vector<std::size_t>& indices, int offset);
// Replaces every Detected trace by `detected` (drawn traces and knot marks are kept).
Annotations replaceDetectedTraces(const Annotations& annotations, std::vector<RingTrace> detected);

// Detected contours (integer pixels of a ring-localization image of imageSize pixels; pixel centres
// at +0.5) as Detected traces in face mm, simplified to within simplifyPx pixels.
std::vector<RingTrace> tracesFromContours(const std::vector<FaceContour>& contours, const Block& block,
                                          glm::ivec2 imageSize, float simplifyPx = 0.3f);

// --- Mokume annotation images (Appendix A.1.2) ------------------------------------------------------
//
// Numbered rings: `<F>_ann.png`, one channel (the first channel is used), 8 bits, 256 x 256 or the face
// photo's size; each pixel's value is the year of the ring trace through it, 255 is background.
// Knots: `<F>_knot.png`, the pixels with grey value 180..220 mark a knot's centre on that face (each
// connected group of such pixels is one mark, at its centroid). Reading and writing the files:
// io/mokume_annotation_files.hpp.

inline constexpr const char* kMokumeRingSuffix = "_ann";
inline constexpr const char* kMokumeKnotSuffix = "_knot";

// Numbered traces of one face from a Mokume ring image: the pixels of each value are thinned to
// one-pixel lines and linked into polylines (one per connected stroke; branches become separate
// traces), kept when at least minPixels long. Origin Drawn.
std::vector<RingTrace> ringTracesFromImage(const GrayImage8& image, FaceId face, const Block& block,
                                           int minPixels = 3);
// The numbered traces of `face` rasterised (8-connected, one pixel wide) into an image of imageSize,
// background 255. Years are clamped to 0..254. Unnumbered traces are not written.
GrayImage8 ringImageFromTraces(const Annotations& annotations, FaceId face, const Block& block,
                               glm::ivec2 imageSize);
// Knot marks of one face (knot ids 0, 1, ... in the order found: row-major by centroid).
std::vector<KnotMark> knotMarksFromImage(const GrayImage8& image, FaceId face, const Block& block);
// Background 0, a disc of grey 200 (radius 2 px) at each mark of `face`.
GrayImage8 knotImageFromMarks(const Annotations& annotations, FaceId face, const Block& block,
                              glm::ivec2 imageSize);

// The image size used for export when there is no photo: Mokume's 6.4 px/mm (256 px on 40 mm).
glm::ivec2 mokumeImageSize(const Block& block, FaceId face);

}  // namespace kerf
