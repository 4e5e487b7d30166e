#pragma once
// Undo commands of the editor (QUndoStack). Each stores both values and asks the Document to apply
// one or the other. Parameter and cut-plane edits merge while a drag is under way (tiled's
// ChangeValue pattern): the command stays open until an edit with finished = true arrives, and a drag
// that ends where it started leaves no step behind.
#include <QImage>
#include <QUndoCommand>
#include <array>
#include <optional>

#include "field/block_knots.hpp"
#include "field/growth_rates.hpp"
#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"
#include "params/parameter_schema.hpp"
#include "rings/annotations.hpp"

namespace kerf {

class Document;

enum CommandId { kCutPlaneCommand = 1, kParameterCommandBase = 1000 };

class SetParameterCommand : public QUndoCommand {
 public:
  SetParameterCommand(Document* document, std::size_t index, std::array<float, 3> before,
                      std::array<float, 3> after, bool finished);
  void undo() override;
  void redo() override;
  int id() const override { return kParameterCommandBase + static_cast<int>(index_); }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  Document* document_;
  std::size_t index_;
  std::array<float, 3> before_, after_;
  bool finished_;
};

class SetAllParametersCommand : public QUndoCommand {
 public:
  SetAllParametersCommand(Document* document, const WoodParameters& before, const WoodParameters& after,
                          const QString& text);
  void undo() override;
  void redo() override;

 private:
  Document* document_;
  WoodParameters before_, after_;
};

// The growth field as a whole (a fit's result): parameters and explicit rates, before and after.
class SetGrowthFieldCommand : public QUndoCommand {
 public:
  // A whole growth field: parameters, explicit rates (or none) and the knots in it.
  struct Field {
    WoodParameters params;
    std::optional<GrowthRates> rates;
    std::vector<BlockKnot> knots;
  };
  SetGrowthFieldCommand(Document* document, Field before, Field after, const QString& text);
  void undo() override;
  void redo() override;

 private:
  Document* document_;
  Field before_, after_;
};

class SetCutPlaneCommand : public QUndoCommand {
 public:
  SetCutPlaneCommand(Document* document, const CutPlaneSetting& before, const CutPlaneSetting& after,
                     bool finished);
  void undo() override;
  void redo() override;
  int id() const override { return kCutPlaneCommand; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  Document* document_;
  CutPlaneSetting before_, after_;
  bool finished_;
};

// The annotations (ring traces, knot marks) before and after one edit of them.
class SetAnnotationsCommand : public QUndoCommand {
 public:
  SetAnnotationsCommand(Document* document, Annotations before, Annotations after, const QString& text);
  void undo() override;
  void redo() override;

 private:
  Document* document_;
  Annotations before_, after_;
};

class ReplacePhotoCommand : public QUndoCommand {
 public:
  ReplacePhotoCommand(Document* document, FaceId face, QString beforePath, QImage beforeImage,
                      QString afterPath, QImage afterImage);
  void undo() override;
  void redo() override;

 private:
  Document* document_;
  FaceId face_;
  QString beforePath_, afterPath_;
  QImage beforeImage_, afterImage_;
};

// The block's size and the six face photos together (File > Import Photos).
class SetBlockAndPhotosCommand : public QUndoCommand {
 public:
  SetBlockAndPhotosCommand(Document* document, const Block& beforeBlock, std::array<QString, 6> beforePaths,
                           std::array<QImage, 6> beforeImages, const Block& afterBlock,
                           std::array<QString, 6> afterPaths, std::array<QImage, 6> afterImages,
                           const QString& text);
  void undo() override;
  void redo() override;

 private:
  Document* document_;
  Block beforeBlock_, afterBlock_;
  std::array<QString, 6> beforePaths_, afterPaths_;
  std::array<QImage, 6> beforeImages_, afterImages_;
};

}  // namespace kerf
