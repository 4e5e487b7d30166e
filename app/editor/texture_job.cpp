#include "texture_job.hpp"

#include "io/image.hpp"
#include "qt_image.hpp"

namespace kerf {

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
