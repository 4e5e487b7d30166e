#include "texture_job.hpp"

#include "io/image.hpp"

namespace kerf {
namespace {

Image fromQImage(const QImage& photo) {
  const QImage rgb = photo.convertToFormat(QImage::Format_RGB888);
  Image image(rgb.width(), rgb.height(), 3);
  for (int y = 0; y < rgb.height(); ++y) {
    const uchar* line = rgb.constScanLine(y);
    float* out = image.pixel(0, y);
    for (int i = 0; i < 3 * rgb.width(); ++i) out[i] = line[i] / 255.0f;
  }
  return image;
}

}  // namespace

TextureJobResult inferTextureFromPhotos(const Block& block, const WoodParameters& current,
                                        const GrowthRates& rates, const std::array<QImage, 6>& photos,
                                        const TextureInferenceOptions& options, const Progress& progress,
                                        const TexturePreview& preview) {
  std::array<Image, 6> images;
  for (int i = 0; i < 6; ++i)
    if (!photos[i].isNull()) images[i] = fromQImage(photos[i]);
  TextureInferenceOptions withPreview = options;
  if (preview) withPreview.preview = preview;
  const TextureInferenceResult result = inferTexture(block, current, rates, images, withPreview, progress);
  TextureJobResult out{result.params, {}, result.lossBefore, result.lossAfter};
  for (const std::string& line : formatTextureInferenceReport(result))
    out.report << QString::fromStdString(line);
  return out;
}

}  // namespace kerf
