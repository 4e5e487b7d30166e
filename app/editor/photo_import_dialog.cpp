#include "photo_import_dialog.hpp"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>

#include "background_pool.hpp"
#include "corner_picker_view.hpp"
#include "faces_view.hpp"
#include "io/image.hpp"
#include "qt_image.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

constexpr int kPreviewPhotoSide = 1600;  // longest side of the reduced copy the dialog works on
constexpr float kPreviewFaceSide = 200;  // px of the longest face side in the preview cross

const char* const kSideNames[4] = {
    QT_TRANSLATE_NOOP("PhotoImportDialog", "top"), QT_TRANSLATE_NOOP("PhotoImportDialog", "right"),
    QT_TRANSLATE_NOOP("PhotoImportDialog", "bottom"), QT_TRANSLATE_NOOP("PhotoImportDialog", "left")};

QString letterOf(FaceId face) {
  return QString(QChar(faceLetter(face)));
}

}  // namespace

struct PhotoImportDialog::Loaded {
  Image preview;
  QSize size;
  QString error;
};

struct PhotoImportDialog::Photo {
  QString path;
  bool loaded = false;
  QSize size;             // full size
  Image preview;          // reduced copy, float
  QImage shown;           // the same for display
  QIcon icon;             // thumbnail for the list
  glm::vec2 scale{1.0f};  // preview pixels per photo pixel
  std::optional<FaceId> face;
  FacePhotoSetup setup;
  WhiteBalanceMode balance = WhiteBalanceMode::None;
  std::optional<QRectF> patch;
  QImage rectified;    // preview of the face
  bool dirty = false;  // rectified is out of date (a drag under way): the preview timer redoes it
  QString problem;
  std::unique_ptr<QFutureWatcher<Loaded>> watcher;
};

PhotoImportDialog::PhotoImportDialog(const Block& block, const std::array<QImage, 6>& currentPhotos,
                                     QWidget* parent)
    : QDialog(parent), currentPhotos_(currentPhotos) {
  setWindowTitle(tr("Import Photos of the Block's Faces"));
  buildUi();
  updating_ = true;
  setBlockSize(block.size());
  updating_ = false;
  previewTimer_.setSingleShot(true);
  connect(&previewTimer_, &QTimer::timeout, this, &PhotoImportDialog::updatePreviews);
  schedulePreview(true);
  showCurrent();
  resize(1360, 800);
}

PhotoImportDialog::~PhotoImportDialog() = default;

void PhotoImportDialog::buildUi() {
  // Left: the photos and what each one is.
  auto* left = new QWidget(this);
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  list_ = new QListWidget(left);
  list_->setIconSize(QSize(48, 48));
  list_->setToolTip(tr("The photos to import; pick one to mark its face's corners"));
  leftLayout->addWidget(list_, 1);
  auto* listButtons = new QHBoxLayout;
  auto* addButton = new QPushButton(tr("Add Photos…"), left);
  addButton->setToolTip(
      tr("Add photos of the block's faces; a name starting \"A_\" .. \"F_\" picks the face"));
  removeButton_ = new QPushButton(tr("Remove"), left);
  removeButton_->setToolTip(tr("Leave this photo out of the import"));
  listButtons->addWidget(addButton);
  listButtons->addWidget(removeButton_);
  leftLayout->addLayout(listButtons);

  auto* photoBox = new QGroupBox(tr("This photo"), left);
  auto* photoForm = new QFormLayout(photoBox);
  faceCombo_ = new QComboBox(photoBox);
  faceCombo_->addItem(tr("— not used —"));
  const QString faceNames[6] = {tr("A  (long grain, front)"), tr("B  (end grain, top)"),
                                tr("C  (long grain, left)"),  tr("D  (end grain, bottom)"),
                                tr("E  (long grain, right)"), tr("F  (long grain, back)")};
  for (const QString& name : faceNames) faceCombo_->addItem(name);
  faceCombo_->setToolTip(
      tr("Which face of the block this photo shows. B and D are the end-grain faces, where the pith runs "
         "out; A, C, E and F the long-grain faces, laid out as in the unfolded cross on the right"));
  photoForm->addRow(tr("Face"), faceCombo_);

  auto* turnRow = new QHBoxLayout;
  auto* turnLeft = new QToolButton(photoBox);
  turnLeft->setText(tr("⟲ 90°"));
  turnLeft->setToolTip(tr("Turn the face a quarter turn anticlockwise"));
  auto* turnRight = new QToolButton(photoBox);
  turnRight->setText(tr("⟳ 90°"));
  turnRight->setToolTip(tr("Turn the face a quarter turn clockwise"));
  flipButton_ = new QToolButton(photoBox);
  flipButton_->setText(tr("Mirror"));
  flipButton_->setCheckable(true);
  flipButton_->setToolTip(
      tr("Mirror the face left to right (for a photo taken in a mirror or a scan made face down)"));
  turnLabel_ = new QLabel(photoBox);
  turnRow->addWidget(turnLeft);
  turnRow->addWidget(turnRight);
  turnRow->addWidget(flipButton_);
  turnRow->addWidget(turnLabel_, 1);
  photoForm->addRow(tr("Turn"), turnRow);

  auto* balanceRow = new QHBoxLayout;
  balanceCombo_ = new QComboBox(photoBox);
  balanceCombo_->addItems({tr("None"), tr("Automatic"), tr("Neutral patch")});
  balanceCombo_->setToolTip(
      tr("Correct the colour of the light. Automatic takes the brightest surfaces of the photo (paper, "
         "bench, sheen) as white; a neutral patch (grey card, white paper) picked on the photo is surer"));
  pickPatchButton_ = new QToolButton(photoBox);
  pickPatchButton_->setText(tr("Pick Patch"));
  pickPatchButton_->setCheckable(true);
  pickPatchButton_->setToolTip(
      tr("Drag a rectangle on the photo over something neutral: a grey card, white paper, unfinished maple"));
  balanceRow->addWidget(balanceCombo_, 1);
  balanceRow->addWidget(pickPatchButton_);
  photoForm->addRow(tr("White balance"), balanceRow);
  leftLayout->addWidget(photoBox);
  photoControls_ = {faceCombo_,    turnLeft,         turnRight,    flipButton_,
                    balanceCombo_, pickPatchButton_, removeButton_};

  // Centre: the photo with the corner handles.
  auto* centre = new QWidget(this);
  auto* centreLayout = new QVBoxLayout(centre);
  centreLayout->setContentsMargins(0, 0, 0, 0);
  picker_ = new CornerPickerView(centre);
  picker_->setToolTip(tr("Drag the numbered handles onto the corners of the face"));
  centreLayout->addWidget(picker_, 1);
  hint_ = new QLabel(
      tr("Drag handles 1–4 onto the face's corners, clockwise; 1 becomes the top-left before turning. A "
         "loupe "
         "shows the corner close up; arrow keys nudge the selected handle a pixel (Shift: 10). The blue side "
         "becomes the face's top; each side names the face across that edge, so rings run on round the "
         "block."),
      centre);
  hint_->setWordWrap(true);
  centreLayout->addWidget(hint_);

  // Right: the cross, the block, the output.
  auto* right = new QWidget(this);
  auto* rightLayout = new QVBoxLayout(right);
  rightLayout->setContentsMargins(0, 0, 0, 0);
  preview_ = new FacesView(right);
  preview_->setAcceptDrops(false);
  preview_->setCaption(tr("Preview"), tr("as the faces will be written"));
  preview_->setMinimumSize(360, 270);
  preview_->setToolTip(
      tr("The rectified faces in the unfolded cross; faces without a new photo keep the "
         "document's photo"));
  rightLayout->addWidget(preview_, 1);

  auto* blockBox = new QGroupBox(tr("Block"), right);
  auto* blockForm = new QFormLayout(blockBox);
  const QString sizeNames[3] = {tr("Width W (x)"), tr("Length H (y, along the grain)"),
                                tr("Thickness D (z)")};
  const QString sizeTips[3] = {
      tr("Width of the block between faces C and E, in mm (measure it with calipers)"),
      tr("Length of the block along the grain, between the end-grain faces B and D, in mm"),
      tr("Thickness of the block between faces A and F, in mm")};
  for (int i = 0; i < 3; ++i) {
    sizeBoxes_[i] = new QDoubleSpinBox(blockBox);
    sizeBoxes_[i]->setRange(1.0, 2000.0);
    sizeBoxes_[i]->setDecimals(1);
    sizeBoxes_[i]->setSuffix(tr(" mm"));
    sizeBoxes_[i]->setToolTip(sizeTips[i]);
    blockForm->addRow(sizeNames[i], sizeBoxes_[i]);
    connect(sizeBoxes_[i], &QDoubleSpinBox::valueChanged, this, [this] {
      if (updating_) return;
      schedulePreview(true);
      updatePicker();
      updateInfo();
    });
  }
  pxPerMmBox_ = new QDoubleSpinBox(blockBox);
  pxPerMmBox_->setRange(1.0, 50.0);
  pxPerMmBox_->setDecimals(1);
  pxPerMmBox_->setValue(10.0);
  pxPerMmBox_->setSuffix(tr(" px/mm"));
  pxPerMmBox_->setToolTip(
      tr("Resolution of the written face images. Ring detection wants at least 5 px/mm; more than the photo "
         "gives only makes bigger files"));
  blockForm->addRow(tr("Face images"), pxPerMmBox_);
  connect(pxPerMmBox_, &QDoubleSpinBox::valueChanged, this, [this] { updateInfo(); });
  rightLayout->addWidget(blockBox);

  auto* folderRow = new QHBoxLayout;
  folderEdit_ = new QLineEdit(right);
  folderEdit_->setToolTip(tr("The folder the faces are written to, as A_col.png .. F_col.png"));
  auto* browse = new QPushButton(tr("Browse…"), right);
  folderRow->addWidget(folderEdit_, 1);
  folderRow->addWidget(browse);
  auto* folderLabel = new QLabel(tr("Write the faces to"), right);
  rightLayout->addWidget(folderLabel);
  rightLayout->addLayout(folderRow);
  connect(folderEdit_, &QLineEdit::textEdited, this, [this] { folderChosen_ = true; });
  connect(browse, &QPushButton::clicked, this, &PhotoImportDialog::chooseFolder);

  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->addWidget(left);
  splitter->addWidget(centre);
  splitter->addWidget(right);
  splitter->setStretchFactor(0, 0);
  splitter->setStretchFactor(1, 3);
  splitter->setStretchFactor(2, 2);
  splitter->setSizes({300, 620, 440});

  info_ = new QLabel(this);
  info_->setWordWrap(true);
  info_->setTextFormat(Qt::RichText);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  okButton_ = buttons->button(QDialogButtonBox::Ok);
  okButton_->setText(tr("Import"));
  okButton_->setToolTip(
      tr("Write the rectified faces and put them and the block size into the document "
         "(one undo step)"));
  connect(buttons, &QDialogButtonBox::accepted, this, &PhotoImportDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(splitter, 1);
  layout->addWidget(info_);
  layout->addWidget(buttons);

  connect(addButton, &QPushButton::clicked, this, &PhotoImportDialog::choosePhotos);
  connect(removeButton_, &QPushButton::clicked, this, [this] { removePhoto(current_); });
  connect(list_, &QListWidget::currentRowChanged, this, [this](int row) {
    if (!updating_) setCurrentPhoto(row);
  });
  connect(faceCombo_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (updating_ || current_ < 0) return;
    setFace(current_, i == 0 ? std::nullopt : std::optional<FaceId>(kAllFaces[i - 1]));
  });
  connect(turnLeft, &QToolButton::clicked, this, [this] {
    if (Photo* p = photo(current_)) setRotation(current_, p->setup.rotationDegrees + 270);
  });
  connect(turnRight, &QToolButton::clicked, this, [this] {
    if (Photo* p = photo(current_)) setRotation(current_, p->setup.rotationDegrees + 90);
  });
  connect(flipButton_, &QToolButton::toggled, this, [this](bool on) {
    if (!updating_ && current_ >= 0) setFlip(current_, on);
  });
  connect(balanceCombo_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (updating_ || current_ < 0) return;
    const auto mode = static_cast<WhiteBalanceMode>(i);
    if (mode == WhiteBalanceMode::Patch && !photo(current_)->patch) {
      pickPatchButton_->setChecked(true);  // the patch comes first
      return;
    }
    setWhiteBalance(current_, mode, photo(current_)->patch);
  });
  connect(pickPatchButton_, &QToolButton::toggled, picker_, &CornerPickerView::setPatchMode);
  connect(picker_, &CornerPickerView::patchPicked, this, &PhotoImportDialog::patchPicked);
  connect(picker_, &CornerPickerView::cornersChanged, this, &PhotoImportDialog::cornersEdited);
}

PhotoImportDialog::Photo* PhotoImportDialog::photo(int index) const {
  return index >= 0 && index < photoCount() ? photos_[index].get() : nullptr;
}

void PhotoImportDialog::addPhotos(const QStringList& paths) {
  for (const QString& path : paths) {
    auto entry = std::make_unique<Photo>();
    entry->path = QFileInfo(path).absoluteFilePath();
    entry->setup.source = entry->path.toStdString();
    entry->face = faceFromFileName(QFileInfo(path).fileName().toStdString());
    if (!entry->face) entry->face = firstFreeFace();
    Photo* raw = entry.get();
    raw->watcher = std::make_unique<QFutureWatcher<Loaded>>();
    connect(raw->watcher.get(), &QFutureWatcher<Loaded>::finished, this,
            [this, raw] { photoLoaded(raw, raw->watcher->result()); });
    const QString file = entry->path;
    photos_.push_back(std::move(entry));
    raw->watcher->setFuture(QtConcurrent::run(backgroundPool(), [file]() -> Loaded {
      Loaded loaded;
      try {
        const Image full = readImage(file.toStdString());
        loaded.size = QSize(full.width, full.height);
        loaded.preview = downscaleImage(full, kPreviewPhotoSide);
      } catch (const std::exception& e) {
        loaded.error = QString::fromUtf8(e.what());
      }
      return loaded;
    }));
  }
  if (!folderChosen_ && !photos_.empty())
    folderEdit_->setText(QDir(QFileInfo(photos_.front()->path).absolutePath()).filePath("kerf-faces"));
  if (current_ < 0 && !photos_.empty()) current_ = 0;
  updateList();
  showCurrent();
}

void PhotoImportDialog::photoLoaded(Photo* photo, const Loaded& loaded) {
  const auto it =
      std::find_if(photos_.begin(), photos_.end(), [&](const auto& p) { return p.get() == photo; });
  if (it == photos_.end()) return;
  if (!loaded.error.isEmpty()) {
    lastError_ = loaded.error;
    info_->setText(QStringLiteral("<span style='color:#e05050'>%1</span>").arg(loaded.error.toHtmlEscaped()));
    removePhoto(static_cast<int>(it - photos_.begin()));
  } else {
    photo->loaded = true;
    photo->size = loaded.size;
    photo->preview = loaded.preview;
    photo->shown = toQImage(loaded.preview);
    photo->icon =
        QIcon(QPixmap::fromImage(photo->shown.scaled(96, 96, Qt::KeepAspectRatio, Qt::SmoothTransformation)));
    photo->scale = {static_cast<float>(loaded.preview.width) / loaded.size.width(),
                    static_cast<float>(loaded.preview.height) / loaded.size.height()};
    if (photo->setup.corners == std::array<glm::vec2, 4>{}) photo->setup.corners = defaultCorners(*photo);
    if (photo->balance != WhiteBalanceMode::None)
      setWhiteBalance(static_cast<int>(it - photos_.begin()), photo->balance, photo->patch);
    rectifyPreview(*photo);
    updateList();
    if (photo == this->photo(current_)) showCurrent();
    schedulePreview(false);
  }
  if (!isLoading()) emit photosLoaded();
}

bool PhotoImportDialog::isLoading() const {
  return std::any_of(photos_.begin(), photos_.end(), [](const auto& p) { return !p->loaded; });
}

QString PhotoImportDialog::photoPath(int index) const {
  const Photo* p = photo(index);
  return p ? p->path : QString();
}

QSize PhotoImportDialog::photoSize(int index) const {
  const Photo* p = photo(index);
  return p ? p->size : QSize();
}

void PhotoImportDialog::removePhoto(int index) {
  if (!photo(index)) return;
  // The watcher may be the sender of the signal being handled: delete it later.
  if (photos_[index]->watcher) photos_[index]->watcher.release()->deleteLater();
  photos_.erase(photos_.begin() + index);
  if (current_ >= photoCount()) current_ = photoCount() - 1;
  updateList();
  showCurrent();
  schedulePreview(true);
}

void PhotoImportDialog::setCurrentPhoto(int index) {
  if (!photo(index) || index == current_) return;
  pickPatchButton_->setChecked(false);
  current_ = index;
  showCurrent();
}

std::optional<FaceId> PhotoImportDialog::firstFreeFace() const {
  for (FaceId face : kAllFaces)
    if (std::none_of(photos_.begin(), photos_.end(), [&](const auto& p) { return p->face == face; }))
      return face;
  return std::nullopt;
}

glm::vec2 PhotoImportDialog::faceMm(FaceId face) const {
  const FaceFrame frame = Block(blockSize()).face(face);
  return {frame.widthMm, frame.heightMm};
}

std::array<glm::vec2, 4> PhotoImportDialog::defaultCorners(const Photo& photo) const {
  // A rectangle of the face's proportions (as it lies before turning) over the middle 60% of the photo.
  glm::vec2 mm = photo.face ? faceMm(*photo.face) : glm::vec2(1.0f);
  if (photo.setup.rotationDegrees % 180 != 0) mm = {mm.y, mm.x};
  const glm::vec2 size(photo.size.width(), photo.size.height());
  const float scale = 0.6f * std::min(size.x / mm.x, size.y / mm.y);
  const glm::vec2 half = mm * scale * 0.5f, centre = size * 0.5f;
  return {centre - half, centre + glm::vec2(half.x, -half.y), centre + half,
          centre + glm::vec2(-half.x, half.y)};
}

std::optional<FaceId> PhotoImportDialog::face(int index) const {
  const Photo* p = photo(index);
  return p ? p->face : std::nullopt;
}

void PhotoImportDialog::setFace(int index, std::optional<FaceId> face) {
  Photo* p = photo(index);
  if (!p || p->face == face) return;
  p->face = face;
  rectifyPreview(*p);
  updateList();
  if (index == current_) showCurrent();
  schedulePreview(false);
}

FacePhotoSetup PhotoImportDialog::setup(int index) const {
  const Photo* p = photo(index);
  return p ? p->setup : FacePhotoSetup{};
}

void PhotoImportDialog::setCorners(int index, const std::array<glm::vec2, 4>& corners) {
  Photo* p = photo(index);
  if (!p) return;
  p->setup.corners = corners;
  rectifyPreview(*p);
  if (index == current_) updatePicker();
  updateList();
  schedulePreview(false);
}

void PhotoImportDialog::setRotation(int index, int degrees) {
  Photo* p = photo(index);
  if (!p) return;
  p->setup.rotationDegrees = normalizedRotation(degrees);
  rectifyPreview(*p);
  if (index == current_) showCurrent();
  schedulePreview(false);
}

void PhotoImportDialog::setFlip(int index, bool flip) {
  Photo* p = photo(index);
  if (!p) return;
  p->setup.flip = flip;
  rectifyPreview(*p);
  if (index == current_) showCurrent();
  schedulePreview(false);
}

WhiteBalanceMode PhotoImportDialog::whiteBalanceMode(int index) const {
  const Photo* p = photo(index);
  return p ? p->balance : WhiteBalanceMode::None;
}

void PhotoImportDialog::setWhiteBalance(int index, WhiteBalanceMode mode, std::optional<QRectF> patch) {
  Photo* p = photo(index);
  if (!p) return;
  if (mode == WhiteBalanceMode::Patch && !patch) return;
  p->balance = mode;
  if (patch) p->patch = patch;
  if (p->problem.startsWith(tr("White balance"))) p->problem.clear();
  if (p->loaded) {
    try {
      if (mode == WhiteBalanceMode::None) p->setup.whiteBalance = glm::vec3(1.0f);
      if (mode == WhiteBalanceMode::Auto) p->setup.whiteBalance = autoWhiteBalance(p->preview);
      if (mode == WhiteBalanceMode::Patch) {
        const QRectF r = *p->patch;
        p->setup.whiteBalance = whiteBalanceFromPatch(
            p->preview,
            {r.x() * p->scale.x, r.y() * p->scale.y, r.width() * p->scale.x, r.height() * p->scale.y});
      }
    } catch (const InputError& e) {
      lastError_ = QString::fromUtf8(e.what());
      p->balance = WhiteBalanceMode::None;
      p->setup.whiteBalance = glm::vec3(1.0f);
      p->problem = tr("White balance: %1").arg(lastError_);
    }
  }
  rectifyPreview(*p);
  if (index == current_) showCurrent();
  schedulePreview(false);
}

glm::vec3 PhotoImportDialog::blockSize() const {
  return {static_cast<float>(sizeBoxes_[0]->value()), static_cast<float>(sizeBoxes_[1]->value()),
          static_cast<float>(sizeBoxes_[2]->value())};
}

void PhotoImportDialog::setBlockSize(glm::vec3 sizeMm) {
  for (int i = 0; i < 3; ++i) sizeBoxes_[i]->setValue(sizeMm[i]);
}

float PhotoImportDialog::pxPerMm() const {
  return static_cast<float>(pxPerMmBox_->value());
}

void PhotoImportDialog::setPxPerMm(float pxPerMm) {
  pxPerMmBox_->setValue(pxPerMm);
}

QString PhotoImportDialog::outputFolder() const {
  return folderEdit_->text().trimmed();
}

void PhotoImportDialog::setOutputFolder(const QString& folder) {
  folderEdit_->setText(folder);
  folderChosen_ = true;
}

PhotoImportPlan PhotoImportDialog::plan() const {
  if (isLoading()) throw InputError(tr("The photos are still loading.").toStdString());
  PhotoImportPlan plan;
  plan.block = Block(blockSize());
  plan.pxPerMm = pxPerMm();
  plan.folder = outputFolder();
  std::array<QString, 6> names;
  for (const auto& p : photos_) {
    if (!p->face) continue;
    const int i = faceIndex(*p->face);
    const QString name = QFileInfo(p->path).fileName();
    if (plan.faces[i])
      throw InputError(tr("%1 and %2 are both assigned to face %3; give each face one photo.")
                           .arg(names[i], name, letterOf(*p->face))
                           .toStdString());
    try {
      validateCorners(p->setup.corners, {p->size.width(), p->size.height()});
    } catch (const InputError& e) {
      throw InputError(
          tr("%1 (face %2): %3").arg(name, letterOf(*p->face), QString::fromUtf8(e.what())).toStdString());
    }
    plan.faces[i] = p->setup;
    names[i] = name;
  }
  if (plan.faceCount() == 0)
    throw InputError(
        tr("No photo is assigned to a face: add photos and choose the face each one shows.").toStdString());
  if (plan.folder.isEmpty()) throw InputError(tr("Choose the folder to write the faces to.").toStdString());
  return plan;
}

QString PhotoImportDialog::problems() const {
  QStringList list;
  for (const auto& p : photos_)
    if (!p->problem.isEmpty())
      list << QStringLiteral("%1: %2").arg(QFileInfo(p->path).fileName(), p->problem);
  return list.join('\n');
}

void PhotoImportDialog::accept() {
  PhotoImportPlan plan;
  try {
    plan = this->plan();
  } catch (const InputError& e) {
    lastError_ = QString::fromUtf8(e.what());
    info_->setText(QStringLiteral("<span style='color:#e05050'>%1</span>").arg(lastError_.toHtmlEscaped()));
    auto* box = new QMessageBox(QMessageBox::Warning, windowTitle(), lastError_, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    return;
  }
  QStringList existing;
  for (FaceId face : kAllFaces)
    if (plan.faces[faceIndex(face)] && QFileInfo::exists(importedFacePath(plan.folder, face)))
      existing << QFileInfo(importedFacePath(plan.folder, face)).fileName();
  if (askBeforeReplacing_ && !existing.isEmpty() &&
      QMessageBox::question(this, windowTitle(),
                            tr("%1 already has %2. Replace?").arg(plan.folder, existing.join(", "))) !=
          QMessageBox::Yes)
    return;
  lastError_.clear();
  QDialog::accept();
}

void PhotoImportDialog::chooseFolder() {
  const QString folder =
      QFileDialog::getExistingDirectory(this, tr("Folder for the face images"), outputFolder());
  if (!folder.isEmpty()) setOutputFolder(folder);
}

void PhotoImportDialog::choosePhotos() {
  const QString start = photos_.empty() ? QString() : QFileInfo(photos_.back()->path).absolutePath();
  const QStringList files = QFileDialog::getOpenFileNames(
      this, tr("Photos of the block's faces"), start,
      tr("Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.webp);;All files (*)"));
  if (!files.isEmpty()) addPhotos(files);
}

void PhotoImportDialog::cornersEdited(bool finished) {
  Photo* p = photo(current_);
  if (!p || !p->loaded) return;
  for (int k = 0; k < 4; ++k)
    p->setup.corners[k] = {static_cast<float>(picker_->corners()[k].x()),
                           static_cast<float>(picker_->corners()[k].y())};
  // Coalesced: a drag sends many moves, the timer rectifies once per burst.
  p->dirty = true;
  schedulePreview(false);
  if (finished) updateList();
  updateInfo();
}

void PhotoImportDialog::patchPicked(QRectF patch) {
  pickPatchButton_->setChecked(false);
  if (current_ >= 0) setWhiteBalance(current_, WhiteBalanceMode::Patch, patch);
}

void PhotoImportDialog::updateList() {
  updating_ = true;
  list_->clear();
  std::array<int, 6> uses{};
  for (const auto& p : photos_)
    if (p->face) ++uses[faceIndex(*p->face)];
  for (const auto& p : photos_) {
    const QString name = QFileInfo(p->path).fileName();
    QString text = (p->face ? letterOf(*p->face) : QStringLiteral("–")) + QStringLiteral("  ") + name;
    if (!p->loaded) text += tr("  (loading…)");
    auto* item = new QListWidgetItem(text, list_);
    if (!p->icon.isNull()) item->setIcon(p->icon);
    const bool clash = p->face && uses[faceIndex(*p->face)] > 1;
    if (clash || !p->problem.isEmpty()) {
      item->setForeground(QColor(224, 80, 80));
      item->setToolTip(clash ? tr("Another photo is assigned to face %1 too").arg(letterOf(*p->face))
                             : p->problem);
    } else {
      item->setToolTip(p->path);
    }
  }
  list_->setCurrentRow(current_);
  updating_ = false;
}

void PhotoImportDialog::showCurrent() {
  const Photo* p = photo(current_);
  updating_ = true;
  for (QWidget* w : photoControls_) w->setEnabled(p != nullptr);
  if (p) {
    faceCombo_->setCurrentIndex(p->face ? faceIndex(*p->face) + 1 : 0);
    flipButton_->setChecked(p->setup.flip);
    turnLabel_->setText(
        tr("%1°%2").arg(p->setup.rotationDegrees).arg(p->setup.flip ? tr(", mirrored") : QString()));
    balanceCombo_->setCurrentIndex(static_cast<int>(p->balance));
    picker_->setImage(p->loaded ? p->shown : QImage(), p->size);
    picker_->setPatch(p->patch);
  } else {
    picker_->setImage({}, {});
    turnLabel_->clear();
  }
  if (list_->currentRow() != current_) list_->setCurrentRow(current_);
  updating_ = false;
  updatePicker();
  updateInfo();
}

void PhotoImportDialog::updatePicker() {
  const Photo* p = photo(current_);
  if (!p) return;
  std::array<QPointF, 4> corners;
  for (int k = 0; k < 4; ++k) corners[k] = {p->setup.corners[k].x, p->setup.corners[k].y};
  picker_->setCorners(corners);
  std::array<QString, 4> labels;
  int top = 0;
  for (int k = 0; k < 4; ++k) {
    const int side = orientedSide(k, p->setup.rotationDegrees, p->setup.flip);
    if (side == 0) top = k;
    labels[k] = tr(kSideNames[side]);
    if (p->face) labels[k] += QStringLiteral(" · ") + letterOf(faceEdgeNeighbours(*p->face)[side]);
  }
  picker_->setSideLabels(labels);
  picker_->setHighlightedSide(top);
}

void PhotoImportDialog::updateInfo() {
  const Photo* p = photo(current_);
  QStringList lines;
  if (p && p->loaded) {
    QString line =
        tr("%1: %2 × %3 px").arg(QFileInfo(p->path).fileName()).arg(p->size.width()).arg(p->size.height());
    if (p->face) {
      const glm::vec2 mm = faceMm(*p->face);
      const glm::ivec2 out = Block(blockSize()).faceImageSize(*p->face, pxPerMm());
      const glm::vec2 resolution = photoResolution(p->setup.corners, mm, p->setup.rotationDegrees);
      line += tr(" · face %1 is %2 × %3 mm → %4 × %5 px · the photo gives %6–%7 px/mm")
                  .arg(letterOf(*p->face))
                  .arg(mm.x, 0, 'g', 4)
                  .arg(mm.y, 0, 'g', 4)
                  .arg(out.x)
                  .arg(out.y)
                  .arg(resolution.x, 0, 'f', 1)
                  .arg(resolution.y, 0, 'f', 1);
      if (pxPerMm() > resolution.x * 1.05f)
        line += QStringLiteral(" <span style='color:#d09030'>%1</span>")
                    .arg(tr("(more px/mm than the photo has: the face will be soft)"));
    }
    lines << line;
    if (p->setup.whiteBalance != glm::vec3(1.0f))
      lines << tr("White balance gains: red %1, green %2, blue %3")
                   .arg(p->setup.whiteBalance.x, 0, 'f', 3)
                   .arg(p->setup.whiteBalance.y, 0, 'f', 3)
                   .arg(p->setup.whiteBalance.z, 0, 'f', 3);
  } else if (p) {
    lines << tr("Loading %1…").arg(QFileInfo(p->path).fileName());
  }
  for (const QString& problem : problems().split('\n', Qt::SkipEmptyParts))
    lines << QStringLiteral("<span style='color:#e05050'>%1</span>").arg(problem.toHtmlEscaped());
  info_->setText(lines.join(QStringLiteral("<br>")));
}

void PhotoImportDialog::schedulePreview(bool all) {
  previewAll_ = previewAll_ || all;
  previewTimer_.start(all ? 0 : 15);
}

void PhotoImportDialog::rectifyPreview(Photo& photo) {
  photo.rectified = QImage();
  photo.dirty = false;
  if (!photo.loaded || !photo.face) {
    photo.problem.clear();
    return;
  }
  const Block block(blockSize());
  const glm::vec3 size = block.size();
  const float previewPxPerMm = std::min(pxPerMm(), kPreviewFaceSide / std::max({size.x, size.y, size.z}));
  FacePhotoSetup scaled = photo.setup;
  for (glm::vec2& c : scaled.corners) c *= photo.scale;
  try {
    validateCorners(photo.setup.corners, {photo.size.width(), photo.size.height()});
    photo.rectified =
        toQImage(rectifyFace(photo.preview, scaled, block.faceImageSize(*photo.face, previewPxPerMm)));
    if (!photo.problem.startsWith(tr("White balance"))) photo.problem.clear();
  } catch (const InputError& e) {
    photo.problem = QString::fromUtf8(e.what());
  }
}

void PhotoImportDialog::updatePreviews() {
  const QString problemsBefore = problems();
  for (auto& p : photos_)
    if (previewAll_ || p->dirty) rectifyPreview(*p);
  if (problems() != problemsBefore) updateList();  // the list marks photos with a problem
  previewAll_ = false;
  previews_ = {};
  for (const auto& p : photos_)
    if (p->face && !p->rectified.isNull()) previews_[faceIndex(*p->face)] = p->rectified;
  std::array<QImage, 6> shown = currentPhotos_;
  for (int i = 0; i < 6; ++i)
    if (!previews_[i].isNull()) shown[i] = previews_[i];
  preview_->setBlock(Block(blockSize()));
  preview_->setPhotos(shown);
  updateInfo();
  emit previewUpdated();
}

}  // namespace kerf
