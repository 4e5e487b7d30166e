#include "document.hpp"

#include <QDir>
#include <QFileInfo>
#include <nlohmann/json.hpp>

#include "document_commands.hpp"
#include "util/error.hpp"

namespace kerf {

Document::Document(QObject* parent) : QObject(parent) {
  connect(&undo_, &QUndoStack::cleanChanged, this, [this] { emit modifiedChanged(isModified()); });
  rebuildModel();
}

void Document::reset(const Project& project, const QString& path, const QString& name,
                     const std::array<QImage, 6>& photos) {
  project_ = project;
  photos_ = photos;
  cutPhotoImage_ = {};
  path_ = path;
  name_ = name;
  undo_.clear();
  undo_.setClean();
  dirtyWithoutUndo_ = false;
  rebuildModel();
  emit documentReset();
  emit modelChanged();
  emit cutPlaneChanged();
  emit photosChanged();
  emit annotationsChanged();
  emit logChanged();
  emit appearanceChanged();
  emit cutPhotoChanged();
  emit modifiedChanged(false);
}

bool Document::hasPhotos() const {
  for (const QImage& photo : photos_)
    if (!photo.isNull()) return true;
  return false;
}

void Document::rebuildModel() {
  model_ = std::make_shared<const WoodModel>(project_);
}

void Document::editParameter(std::size_t index, std::array<float, 3> value, bool finished) {
  std::array<float, 3> before{};
  const auto current = project_.params.components(index);
  for (std::size_t c = current.size(); c < 3; ++c) value[c] = 0.0f;  // scalars use the first component only
  std::copy(current.begin(), current.end(), before.begin());
  WoodParameters candidate = project_.params;  // refuse a bad value before it reaches the undo stack
  std::copy_n(value.begin(), current.size(), candidate.components(index).begin());
  validate(candidate);
  undo_.push(setParameterCommand(this, index, before, value, finished));
}

void Document::applyParameters(const WoodParameters& params, const QString& undoText) {
  validate(params);
  undo_.push(setAllParametersCommand(this, project_.params, params, undoText));
}

void Document::applyGrowthField(const WoodParameters& params, std::optional<GrowthRates> rates,
                                const QString& undoText, std::optional<std::vector<BlockKnot>> knots) {
  validate(params);
  if (rates) rates->validate();
  std::vector<BlockKnot> afterKnots = knots ? std::move(*knots) : project_.knots;
  for (std::size_t i = 0; i < afterKnots.size(); ++i)
    validate(afterKnots[i], "knots[" + std::to_string(i) + "]");
  undo_.push(setGrowthFieldCommand(this, {project_.params, project_.rates, project_.knots},
                                   {params, std::move(rates), std::move(afterKnots)}, undoText));
}

void Document::editBlockKnots(std::vector<BlockKnot> knots, const QString& undoText) {
  for (std::size_t i = 0; i < knots.size(); ++i)
    validate(knots[i], "knot K" + std::to_string(knots[i].id + 1));
  if (knots == project_.knots) return;
  undo_.push(setGrowthFieldCommand(this, {project_.params, project_.rates, project_.knots},
                                   {project_.params, project_.rates, std::move(knots)}, undoText));
}

void Document::editCutPlane(const CutPlaneSetting& setting, bool finished) {
  undo_.push(setCutPlaneCommand(this, cutPlane(), setting, finished));
}

void Document::replacePhoto(FaceId face, const QString& path, const QImage& image) {
  const int i = faceIndex(face);
  undo_.push(replacePhotoCommand(
      this, face, {QString::fromStdString(project_.facePhotos[i].string()), photos_[i]}, {path, image}));
}

void Document::replaceBlockAndPhotos(const Block& block, const std::array<QString, 6>& paths,
                                     const std::array<QImage, 6>& images, const QString& undoText) {
  const Block checked(block.size());  // InputError unless every side is finite and positive
  std::array<QString, 6> beforePaths;
  for (int i = 0; i < 6; ++i) beforePaths[i] = QString::fromStdString(project_.facePhotos[i].string());
  undo_.push(setBlockAndPhotosCommand(this, {project_.block, beforePaths, photos_}, {checked, paths, images},
                                      undoText));
}

void Document::editAnnotations(const Annotations& after, const QString& undoText) {
  if (after == project_.annotations) return;
  undo_.push(setAnnotationsCommand(this, project_.annotations, after, undoText));
}

void Document::setCutEnabled(bool enabled) {
  if (project_.cutEnabled == enabled) return;
  project_.cutEnabled = enabled;
  if (!project_.cutPlane) project_.cutPlane = CutPlaneSetting{};
  dirtyWithoutUndo_ = true;
  emit cutPlaneChanged();
  emit modifiedChanged(true);
}

void Document::setAppearance(Appearance appearance) {
  if (project_.appearance == appearance) return;
  project_.appearance = appearance;
  dirtyWithoutUndo_ = true;
  emit appearanceChanged();
  emit modifiedChanged(true);
}

void Document::setRingUncertainty(RingUncertainty uncertainty) {
  project_.ringUncertainty = std::move(uncertainty);
  dirtyWithoutUndo_ = true;
  emit ringUncertaintyChanged();
  emit modifiedChanged(true);
}

void Document::markModified() {
  dirtyWithoutUndo_ = true;
  emit modifiedChanged(true);
}

void Document::applyParameterValue(std::size_t index, std::array<float, 3> value) {
  const auto target = project_.params.components(index);
  std::copy_n(value.begin(), target.size(), target.begin());
  rebuildModel();
  emit modelChanged();
}

void Document::applyAllParameters(const WoodParameters& params) {
  project_.params = params;
  rebuildModel();
  emit modelChanged();
}

void Document::applyGrowthFieldValue(const WoodParameters& params, const std::optional<GrowthRates>& rates,
                                     const std::vector<BlockKnot>& knots) {
  project_.params = params;
  project_.rates = rates;
  project_.knots = knots;
  rebuildModel();
  emit modelChanged();
}

void Document::applyCutPlane(const CutPlaneSetting& setting) {
  project_.cutPlane = setting;
  emit cutPlaneChanged();
}

void Document::applyPhoto(FaceId face, const QString& path, const QImage& image) {
  project_.facePhotos[faceIndex(face)] = path.toStdString();
  photos_[faceIndex(face)] = image;
  emit photosChanged();
}

void Document::applyBlockAndPhotos(const Block& block, const std::array<QString, 6>& paths,
                                   const std::array<QImage, 6>& images) {
  const bool resized = block.size() != project_.block.size();
  project_.block = block;
  for (int i = 0; i < 6; ++i) project_.facePhotos[i] = paths[i].toStdString();
  photos_ = images;
  if (resized) {
    rebuildModel();
    emit blockChanged();
    emit modelChanged();
  }
  emit photosChanged();
}

void Document::applyAnnotations(const Annotations& annotations) {
  project_.annotations = annotations;
  emit annotationsChanged();
}

void Document::saveAs(const QString& path) {
  saveProject(project_, path.toStdString());
  path_ = QFileInfo(path).absoluteFilePath();
  name_ = QFileInfo(path).completeBaseName();
  dirtyWithoutUndo_ = false;
  undo_.setClean();
  emit documentReset();
  emit modifiedChanged(false);
}

QByteArray Document::snapshot(const QString& folder) const {
  const std::string text = projectToJson(project_, std::filesystem::absolute(folder.toStdString())).dump(2);
  return QByteArray::fromStdString(text);
}

}  // namespace kerf
