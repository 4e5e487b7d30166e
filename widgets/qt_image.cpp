#include "qt_image.hpp"

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {
uchar toByte(float v) {
  return static_cast<uchar>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}
}  // namespace

QImage toQImage(const Image& image) {
  if (image.empty() || image.width <= 0 || image.height <= 0) return {};
  const bool alpha = image.channels == 4;
  QImage out(image.width, image.height, alpha ? QImage::Format_RGBA8888 : QImage::Format_RGB888);
  const int outChannels = alpha ? 4 : 3;
  for (int y = 0; y < image.height; ++y) {
    uchar* row = out.scanLine(y);  // QImage rows are padded to 4 bytes
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.pixel(x, y);
      for (int c = 0; c < outChannels; ++c) row[x * outChannels + c] = toByte(p[image.channels >= 3 ? c : 0]);
    }
  }
  return out;
}

Image fromQImage(const QImage& photo) {
  if (photo.isNull()) return {};
  const QImage rgb = photo.convertToFormat(QImage::Format_RGB888);
  Image image(rgb.width(), rgb.height(), 3);
  for (int y = 0; y < rgb.height(); ++y) {
    const uchar* line = rgb.constScanLine(y);
    float* out = image.pixel(0, y);
    for (int i = 0; i < 3 * rgb.width(); ++i) out[i] = line[i] / 255.0f;
  }
  return image;
}

}  // namespace kerf
