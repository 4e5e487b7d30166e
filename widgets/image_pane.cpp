#include "image_pane.hpp"

#include <QPainter>

namespace kerf {

ImagePane::ImagePane(QWidget* parent) : QWidget(parent) {
  setAutoFillBackground(false);
}

void ImagePane::setImage(const QImage& image, const QString& caption) {
  image_ = image;
  caption_ = caption;
  update();
}

void ImagePane::setPlaceholder(const QString& text) {
  placeholder_ = text;
  update();
}

void ImagePane::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(38, 38, 40));
  painter.setPen(QColor(210, 210, 210));
  if (image_.isNull()) {
    painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap, placeholder_);
    return;
  }
  const int captionHeight = fontMetrics().height() + 8;
  const QRect area = rect().adjusted(8, 8, -8, -8 - captionHeight);
  const QSize fitted = image_.size().scaled(area.size(), Qt::KeepAspectRatio);
  const QRect target(area.center() - QPoint(fitted.width() / 2, fitted.height() / 2), fitted);
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.drawImage(target, image_);
  painter.drawText(QRect(0, height() - captionHeight, width(), captionHeight), Qt::AlignCenter, caption_);
}

}  // namespace kerf
