#pragma once
// A picture fitted into the widget (aspect kept, centred) with a caption under it, or a placeholder text
// while there is none: the editor's Panel view.
#include <QImage>
#include <QString>
#include <QWidget>

namespace kerf {

class ImagePane : public QWidget {
  Q_OBJECT

 public:
  explicit ImagePane(QWidget* parent = nullptr);

  void setImage(const QImage& image, const QString& caption);
  void setPlaceholder(const QString& text);  // shown while there is no image
  const QImage& image() const { return image_; }
  const QString& caption() const { return caption_; }

  QSize sizeHint() const override { return {480, 360}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QImage image_;
  QString caption_, placeholder_;
};

}  // namespace kerf
