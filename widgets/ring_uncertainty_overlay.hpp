#pragma once
// How sure the fit is, drawn over a cut (issue 18 item 4, issue 20 item 3): a translucent tint by the
// 1-sigma ring position (field/ring_uncertainty.hpp), in the steps a woodworker plans with: green where a
// ring lies within +-0.25 mm, yellow about +-0.5 mm, orange +-1 mm, red +-2 mm or worse; a legend; and the
// words for one point ("rings +-0.4 mm here").
#include <QColor>
#include <QImage>
#include <QRectF>
#include <QString>

#include "field/ring_uncertainty.hpp"
#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"

class QPainter;

namespace kerf {

QColor ringUncertaintyColor(float sigmaMm);  // opaque; the overlay draws it translucent
QString ringUncertaintyText(float sigmaMm);  // "rings ±0.4 mm"
// The tint of the cut's bounding rectangle (plane mm) sampled every stepMm, top row = rect.max.y (as the
// cut is drawn); pixels outside the block are transparent.
QImage ringUncertaintyImage(const RingUncertainty& uncertainty, const Block& block, const CutPlane& plane,
                            const PlaneRect& rect, float stepMm);
// The legend, in the top-right corner of `area`.
void drawRingUncertaintyLegend(QPainter& painter, const QRectF& area);

}  // namespace kerf
