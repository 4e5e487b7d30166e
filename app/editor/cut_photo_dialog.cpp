#include "cut_photo_dialog.hpp"

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include "corner_picker_view.hpp"
#include "io/cut_photo.hpp"
#include "util/error.hpp"

namespace kerf {

CutPhotoDialog::CutPhotoDialog(const QImage& photo, const FacePhotoSetup& setup, QWidget* parent)
    : QDialog(parent), setup_(setup), photoSize_(photo.size()), picker_(new CornerPickerView(this)) {
  setWindowTitle(tr("Align Cut Photo"));
  // The picker shows a reduced copy: a phone photo's full size only slows the drawing.
  const QImage shown = photo.width() > 1600 || photo.height() > 1600
                           ? photo.scaled(1600, 1600, Qt::KeepAspectRatio, Qt::SmoothTransformation)
                           : photo;
  picker_->setImage(shown, photo.size());
  auto* help = new QLabel(
      tr("Drag handles 1–4 onto the corners of the sawn surface, clockwise (1 is the cut's top-left before "
         "turning). The thick side becomes the top of the cut as the Cut panel shows it: turn or mirror the "
         "photo until the sides' names match the cut."),
      this);
  help->setWordWrap(true);
  auto makeButton = [this](const QString& text, const QString& tip) {
    auto* button = new QToolButton(this);
    button->setText(text);
    button->setToolTip(tip);
    return button;
  };
  QToolButton* turnLeft = makeButton(tr("⟲ 90°"), tr("Turn the photo a quarter turn anticlockwise"));
  QToolButton* turnRight = makeButton(tr("⟳ 90°"), tr("Turn the photo a quarter turn clockwise"));
  flipButton_ = makeButton(tr("Mirror"), tr("Mirror the photo left to right (a photo of the other half of "
                                            "the board, whose face is the cut seen from behind)"));
  flipButton_->setCheckable(true);
  QToolButton* whole = makeButton(tr("Whole Photo"),
                                  tr("Put the handles on the photo's corners (a photo cropped to the cut)"));
  connect(turnLeft, &QToolButton::clicked, this, [this] { setRotation(setup_.rotationDegrees + 270); });
  connect(turnRight, &QToolButton::clicked, this, [this] { setRotation(setup_.rotationDegrees + 90); });
  connect(flipButton_, &QToolButton::toggled, this, &CutPhotoDialog::setFlip);
  connect(whole, &QToolButton::clicked, this, &CutPhotoDialog::useWholePhoto);
  connect(picker_, &CornerPickerView::cornersChanged, this, &CutPhotoDialog::cornersEdited);

  problem_ = new QLabel(this);
  problem_->setStyleSheet(QStringLiteral("color: #c03030"));
  problem_->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* row = new QHBoxLayout;
  for (QToolButton* button : {turnLeft, turnRight, flipButton_, whole}) row->addWidget(button);
  row->addStretch(1);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(help);
  layout->addWidget(picker_, 1);
  layout->addLayout(row);
  layout->addWidget(problem_);
  layout->addWidget(buttons);
  showSetup();
}

void CutPhotoDialog::setRotation(int degrees) {
  setup_.rotationDegrees = normalizedRotation(((degrees % 360) + 360) % 360);
  showSetup();
}

void CutPhotoDialog::setFlip(bool flip) {
  setup_.flip = flip;
  showSetup();
}

void CutPhotoDialog::useWholePhoto() {
  setup_.corners = wholePhotoCorners({photoSize_.width(), photoSize_.height()});
  showSetup();
}

void CutPhotoDialog::cornersEdited() {
  for (int k = 0; k < 4; ++k)
    setup_.corners[k] = {static_cast<float>(picker_->corners()[k].x()),
                         static_cast<float>(picker_->corners()[k].y())};
  showSetup();
}

void CutPhotoDialog::showSetup() {
  std::array<QPointF, 4> corners;
  for (int k = 0; k < 4; ++k) corners[k] = {setup_.corners[k].x, setup_.corners[k].y};
  picker_->setCorners(corners);
  static const char* const kSides[] = {QT_TR_NOOP("top of the cut"), QT_TR_NOOP("right"),
                                       QT_TR_NOOP("bottom"), QT_TR_NOOP("left")};
  std::array<QString, 4> labels;
  int top = 0;
  for (int k = 0; k < 4; ++k) {
    const int side = orientedSide(k, setup_.rotationDegrees, setup_.flip);
    if (side == 0) top = k;
    labels[k] = tr(kSides[side]);
  }
  picker_->setSideLabels(labels);
  picker_->setHighlightedSide(top);
  flipButton_->blockSignals(true);
  flipButton_->setChecked(setup_.flip);
  flipButton_->blockSignals(false);
  try {
    validateCorners(setup_.corners, {photoSize_.width(), photoSize_.height()});
    problem_->clear();
  } catch (const InputError& e) {
    problem_->setText(QString::fromUtf8(e.what()));
  }
  if (auto* ok = findChild<QDialogButtonBox*>())
    ok->button(QDialogButtonBox::Ok)->setEnabled(problem_->text().isEmpty());
}

}  // namespace kerf
