#include "log_board_faces.hpp"

#include <algorithm>
#include <cmath>

#include "field/knot_field.hpp"
#include "qt_image.hpp"

namespace kerf {

WoodColorMap logColorMap(const LogModel& log, const WoodParameters& params) {
  return log.colorMap.empty() ? woodColorMapFromParameters(params, log.stem.maxRadius()) : log.colorMap;
}

std::array<QImage, 6> renderLogBoardFaces(const ProjectLog& log, const WoodParameters& params, float pxPerMm,
                                          const Progress& progress) {
  const WoodColorMap colors = logColorMap(log.log, params);
  const KnotField field(log.log, KnotSettings::fromParameters(params));
  const Block block(log.board.size);
  // A long board (a beam, a whole plank) keeps at most kMaxFacePixels along its longest side.
  constexpr float kMaxFacePixels = 1600.0f;
  const glm::vec3 size = log.board.size;
  pxPerMm = std::min(pxPerMm, kMaxFacePixels / std::max({size.x, size.y, size.z}));
  std::array<QImage, 6> faces;
  for (FaceId face : kAllFaces) {
    progress.throwIfCancelled();
    const int i = faceIndex(face);
    const FaceFrame frame = block.face(face);
    BoardRenderOptions options;
    options.face = face;
    options.resolution =
        std::max(8, static_cast<int>(std::lround(std::max(frame.widthMm, frame.heightMm) * pxPerMm)));
    faces[i] = toQImage(
        renderBoardFace(field, colors, log.board, options, nullptr, progress.part(i / 6.0, (i + 1) / 6.0)));
  }
  progress.throwIfCancelled();
  return faces;
}

}  // namespace kerf
