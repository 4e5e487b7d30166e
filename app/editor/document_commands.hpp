#pragma once
// Undo commands of the editor (QUndoStack): each a SwapValueCommand over one of the Document's values,
// applied through the Document's apply… setter. Parameter and cut-plane edits merge while a drag is under
// way: the command stays open until an edit with finished = true arrives, and a drag that ends where it
// started leaves no step behind.
#include <QImage>
#include <QUndoCommand>
#include <array>
#include <optional>
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_rates.hpp"
#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"
#include "io/cut_photo.hpp"
#include "params/parameter_schema.hpp"
#include "rings/annotations.hpp"
#include "swap_value_command.hpp"

namespace kerf {

class Document;

enum CommandId { kCutPlaneCommand = 1, kParameterCommandBase = 1000 };

// A whole growth field (a fit's result): parameters, explicit rates (or none) and the knots in it.
struct GrowthFieldValue {
  WoodParameters params;
  std::optional<GrowthRates> rates;
  std::vector<BlockKnot> knots;
};

// One face's photo: its file and its image.
struct FacePhotoValue {
  QString path;
  QImage image;
};

// The photo of the real cut (its file, alignment and plane) and its pixels.
struct CutPhotoValue {
  std::optional<CutPhoto> photo;
  QImage image;
};

// The block's size and the six face photos together (File > Import Photos).
struct BlockAndPhotosValue {
  Block block;
  std::array<QString, 6> paths;
  std::array<QImage, 6> images;
};

// One parameter (its up to three components); merges while a slider is dragged.
QUndoCommand* setParameterCommand(Document* document, std::size_t index, std::array<float, 3> before,
                                  std::array<float, 3> after, bool finished);
QUndoCommand* setAllParametersCommand(Document* document, const WoodParameters& before,
                                      const WoodParameters& after, const QString& text);
QUndoCommand* setGrowthFieldCommand(Document* document, GrowthFieldValue before, GrowthFieldValue after,
                                    const QString& text);
QUndoCommand* setCutPlaneCommand(Document* document, const CutPlaneSetting& before,
                                 const CutPlaneSetting& after, bool finished);
// The annotations (ring traces, knot marks) before and after one edit of them.
QUndoCommand* setAnnotationsCommand(Document* document, Annotations before, Annotations after,
                                    const QString& text);
QUndoCommand* replacePhotoCommand(Document* document, FaceId face, FacePhotoValue before,
                                  FacePhotoValue after);
QUndoCommand* setBlockAndPhotosCommand(Document* document, BlockAndPhotosValue before,
                                       BlockAndPhotosValue after, const QString& text);
QUndoCommand* setCutPhotoCommand(Document* document, CutPhotoValue before, CutPhotoValue after,
                                 const QString& text);

}  // namespace kerf
