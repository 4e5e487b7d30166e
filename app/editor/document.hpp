#pragma once
// The open document of the editor: the project (block, parameters, growth rates, photos, cut plane),
// its file, and the undo stack through which every edit goes. Views observe its signals; they never
// change it directly. The wood model is rebuilt after each edit (cheap: milliseconds) and shared
// read-only with views and background jobs.
#include <QImage>
#include <QObject>
#include <QString>
#include <QUndoStack>
#include <array>
#include <memory>
#include <optional>

#include "geometry/cut_plane.hpp"
#include "io/project.hpp"
#include "render/wood_model.hpp"

namespace kerf {

class Document : public QObject {
  Q_OBJECT

 public:
  explicit Document(QObject* parent = nullptr);

  // Replaces the whole content (after opening a file); clears the undo history and marks it clean.
  // `path` is a .kerf file, or empty for a document that has no project file yet (a sample folder, the
  // demo in the cache): Save then asks where to save.
  void reset(const Project& project, const QString& path, const QString& name,
             const std::array<QImage, 6>& photos);

  const Project& project() const { return project_; }
  std::shared_ptr<const WoodModel> model() const { return model_; }
  const std::array<QImage, 6>& photos() const { return photos_; }
  bool hasPhotos() const;
  QString filePath() const { return path_; }
  QString name() const { return name_; }
  bool isModified() const { return !undo_.isClean() || dirtyWithoutUndo_; }
  QUndoStack* undoStack() { return &undo_; }
  CutPlaneSetting cutPlane() const { return project_.cutPlane.value_or(CutPlaneSetting{}); }
  bool cutEnabled() const { return project_.cutEnabled; }
  // The ring traces and knot marks (face mm), saved with the project.
  const Annotations& annotations() const { return project_.annotations; }

  // Edits. Each pushes an undo command; unfinished edits of the same thing (a slider or a plane being
  // dragged) merge into one step, closed by the edit with finished = true.
  void editParameter(std::size_t index, std::array<float, 3> value, bool finished);
  void applyParameters(const WoodParameters& params, const QString& undoText);
  // Replaces the growth field as one undo step: the parameters (growth.*, and any others that differ)
  // together with the explicit growth rates (std::nullopt: rates synthesised from the parameters).
  // Validates both first (InputError; nothing is pushed then).
  // knots: the field's knots (Project::knots); std::nullopt keeps the current ones.
  void applyGrowthField(const WoodParameters& params, std::optional<GrowthRates> rates,
                        const QString& undoText, std::optional<std::vector<BlockKnot>> knots = std::nullopt);
  // The block's knots (Project::knots: the knot table's edits) as one undo step of the growth field, the
  // parameters and rates kept. Validates them first (InputError naming the knot; nothing is pushed then).
  void editBlockKnots(std::vector<BlockKnot> knots, const QString& undoText);
  void editCutPlane(const CutPlaneSetting& setting, bool finished);
  void replacePhoto(FaceId face, const QString& path, const QImage& image);
  // The block's size and all six face photos together, as one undo step (File > Import Photos): a null
  // image and empty path leave a face without a photo. Throws InputError for a bad size (nothing pushed).
  void replaceBlockAndPhotos(const Block& block, const std::array<QString, 6>& paths,
                             const std::array<QImage, 6>& images, const QString& undoText);
  // Replaces the annotations as one undo step (nothing is pushed when they are unchanged).
  void editAnnotations(const Annotations& after, const QString& undoText);
  // The log and its board (document_log.cpp); each edit is one undo step, a board drag merges until
  // finished. The block follows the board's size. Throw InputError for a bad log, board or knot.
  const std::optional<ProjectLog>& log() const { return project_.log; }
  void setLog(std::optional<ProjectLog> log, const QString& undoText);
  void editBoard(const Board& board, bool finished);
  void editKnots(std::vector<Knot> knots, const QString& undoText);
  // The cut's visibility is a view setting: saved with the project, but not an undo step.
  void setCutEnabled(bool enabled);
  // How the surfaces are made (Project::appearance): the procedural model, or the block's own photos re-grown
  // along the field (issue 17). A view choice like the cut's visibility: saved, not an undo step.
  Appearance appearance() const { return project_.appearance; }
  void setAppearance(Appearance appearance);
  // How sure the fit is (Project::ringUncertainty): a result of the fit, saved with the project but not
  // an undo step. It holds the fingerprint of its field, so it shows only while that field is the
  // document's (undoing the fit hides it, redoing shows it again).
  void setRingUncertainty(RingUncertainty uncertainty);
  const RingUncertainty* ringUncertainty() const { return project_.currentRingUncertainty(); }
  // The photo of the real cut (Project::cutPhoto) and its pixels (document_cut_photo.cpp). Loading,
  // aligning and removing it are undo steps; the image is null until a saved photo has been read
  // (restoreCutPhotoImage), or when its file could not be.
  const std::optional<CutPhoto>& cutPhoto() const { return project_.cutPhoto; }
  const QImage& cutPhotoImage() const { return cutPhotoImage_; }
  void setCutPhoto(std::optional<CutPhoto> photo, const QImage& image, const QString& undoText);
  // The pixels of the saved photo, read after opening: not an edit (no undo step, not modified).
  void restoreCutPhotoImage(const QImage& image);
  // Marks the document as holding unsaved work (recovered from an autosave).
  void markModified();

  // Writes the project atomically to `path` (photos relative to it) and makes it the document's file.
  // Throws InputError.
  void saveAs(const QString& path);
  // The project as it would be saved next to `folder` (for autosave).
  QByteArray snapshot(const QString& folder) const;

  // Used by the undo commands only: set a value without pushing a command.
  void applyParameterValue(std::size_t index, std::array<float, 3> value);
  void applyAllParameters(const WoodParameters& params);
  void applyGrowthFieldValue(const WoodParameters& params, const std::optional<GrowthRates>& rates,
                             const std::vector<BlockKnot>& knots);
  void applyCutPlane(const CutPlaneSetting& setting);
  void applyPhoto(FaceId face, const QString& path, const QImage& image);
  void applyAnnotations(const Annotations& annotations);
  void applyLog(const std::optional<ProjectLog>& log, const Block& block);
  void applyBoard(const Board& board);
  void applyKnots(const std::vector<Knot>& knots);
  void applyCutPhoto(const std::optional<CutPhoto>& photo, const QImage& image);
  void applyBlockAndPhotos(const Block& block, const std::array<QString, 6>& paths,
                           const std::array<QImage, 6>& images);

 signals:
  void modelChanged();     // parameters or growth rates changed: model() is new
  void cutPlaneChanged();  // setting or visibility
  void annotationsChanged();
  void photosChanged();
  void blockChanged();   // the block's size (the model changes with it: modelChanged follows)
  void documentReset();  // a different document (or file) is now open
  void modifiedChanged(bool modified);
  void logChanged();    // a log attached, removed or its knots edited (modelChanged may follow)
  void boardChanged();  // the board moved or resized
  void ringUncertaintyChanged();
  void appearanceChanged();
  void cutPhotoChanged();

 private:
  void rebuildModel();

  Project project_;
  std::shared_ptr<const WoodModel> model_;
  std::array<QImage, 6> photos_;
  QImage cutPhotoImage_;
  QString path_, name_;
  QUndoStack undo_;
  bool dirtyWithoutUndo_ = false;  // view settings changed since the last save
};

}  // namespace kerf
