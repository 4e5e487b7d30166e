#pragma once
// What the compare displays of the faces view and of the cut panel draw alike, so photo | model and the
// difference look and read the same in both: the split line with its grip, the small tags that say
// which side is which, and the difference heat map's legend (face_difference.hpp's colours).
#include <QRectF>
#include <QString>

class QPainter;

namespace kerf {

// How near the split line (widget pixels) a left press takes it.
inline constexpr qreal kSplitGrabPx = 6;

// The vertical photo | model line at widget x, drawn over `visible`, with a grip half-way down.
void drawSplitLine(QPainter& painter, qreal x, const QRectF& visible);

// A tag in a corner of `area` (e.g. Qt::AlignBottom | Qt::AlignLeft), clipped to `clip`.
void drawCompareTag(QPainter& painter, const QRectF& area, const QRectF& clip, const QString& text,
                    Qt::Alignment corner);

// "photo" left of the line and "model" right of it, where `area` (the compared picture) has room.
void drawSplitTags(QPainter& painter, const QRectF& area, const QRectF& clip, qreal x);

// The heat map's legend in the bottom-right corner of `area`.
void drawDifferenceLegend(QPainter& painter, const QRectF& area);

}  // namespace kerf
