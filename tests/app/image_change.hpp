#pragma once
// How much a picture changed: what the editor tests use to see that a view followed an edit.
#include <QImage>
#include <cstdlib>

namespace kerf::testing {

// Share of pixels that differ noticeably (summed RGB difference over 24) between two pictures; 1 when
// the sizes differ or the first is empty.
inline double changedShare(const QImage& a, const QImage& b) {
  if (a.size() != b.size() || a.isNull()) return 1.0;
  const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
  int changed = 0;
  for (int row = 0; row < x.height(); ++row)
    for (int col = 0; col < x.width(); ++col) {
      const QRgb p = x.pixel(col, row), q = y.pixel(col, row);
      changed +=
          std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q)) > 24;
    }
  return static_cast<double>(changed) / (x.width() * x.height());
}

}  // namespace kerf::testing
