#include "face_difference.hpp"

#include <algorithm>
#include <cstdlib>

namespace kerf {

namespace {

// Integer luma (Rec. 601 weights / 256): cheap, and only its sign and rough size matter here.
int luma(QRgb c) {
  return (77 * qRed(c) + 150 * qGreen(c) + 29 * qBlue(c)) >> 8;
}

int mix(int a, int b, int t256) {
  return a + (b - a) * t256 / 256;
}

}  // namespace

QRgb differenceColour(int difference, int lighter) {
  if (difference <= 0) return qRgb(0, 0, 0);
  // Hue: how much of the difference is lightness (+1 lighter, -1 darker, 0 another hue).
  const int share = std::clamp(lighter * 256 / difference, -256, 256);
  const QRgb towards = share >= 0 ? qRgb(255, 150, 40) : qRgb(60, 150, 255);
  const int s = std::abs(share);
  const int r = mix(255, qRed(towards), s), g = mix(255, qGreen(towards), s), b = mix(255, qBlue(towards), s);
  // Brightness: how large the difference is.
  const int t = std::min(difference, kDifferenceFullScale) * 256 / kDifferenceFullScale;
  return qRgb(r * t / 256, g * t / 256, b * t / 256);
}

QImage differenceHeatMap(const QImage& photo, const QImage& model) {
  if (photo.isNull() || model.isNull()) return {};
  const QImage p = photo.convertToFormat(QImage::Format_RGB32);
  const QImage m = (model.size() == photo.size()
                        ? model
                        : model.scaled(photo.size(), Qt::IgnoreAspectRatio, Qt::SmoothTransformation))
                       .convertToFormat(QImage::Format_RGB32);
  QImage heat(p.size(), QImage::Format_RGB32);
  for (int y = 0; y < p.height(); ++y) {
    const auto* photoRow = reinterpret_cast<const QRgb*>(p.constScanLine(y));
    const auto* modelRow = reinterpret_cast<const QRgb*>(m.constScanLine(y));
    auto* out = reinterpret_cast<QRgb*>(heat.scanLine(y));
    for (int x = 0; x < p.width(); ++x) {
      const QRgb a = photoRow[x], b = modelRow[x];
      const int difference =
          (std::abs(qRed(b) - qRed(a)) + std::abs(qGreen(b) - qGreen(a)) + std::abs(qBlue(b) - qBlue(a))) / 3;
      out[x] = differenceColour(difference, luma(b) - luma(a));
    }
  }
  return heat;
}

std::array<QImage, 6> differenceHeatMaps(const std::array<QImage, 6>& photos,
                                         const std::array<QImage, 6>& models) {
  std::array<QImage, 6> maps;
  for (std::size_t i = 0; i < maps.size(); ++i) maps[i] = differenceHeatMap(photos[i], models[i]);
  return maps;
}

}  // namespace kerf
