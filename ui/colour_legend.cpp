#include "ui/colour_legend.h"

#include <QEvent>
#include <QPainter>

namespace garment::ui {

namespace {
constexpr int kMargin = 8;   // from the parent's corner, and inside the panel
constexpr int kSpacing = 6;  // between swatch and text
constexpr int kLineGap = 3;  // between lines
}  // namespace

ColourLegend::ColourLegend(QWidget* parent) : QWidget(parent) {
  setObjectName("colour_legend");
  setAttribute(Qt::WA_TransparentForMouseEvents);
  parent->installEventFilter(this);
  hide();
}

void ColourLegend::setEntries(const QList<LegendEntry>& entries) {
  if (entries == entries_) return;
  entries_ = entries;
  setVisible(!entries_.isEmpty());
  place();
  update();
}

QRect ColourLegend::swatchRect(int entry) const {
  const int line = fontMetrics().height();
  return QRect(kMargin, kMargin + entry * (line + kLineGap), line, line);
}

QSize ColourLegend::sizeHint() const {
  int text_width = 0;
  for (const LegendEntry& entry : entries_)
    text_width = std::max(text_width, fontMetrics().horizontalAdvance(entry.text));
  const int line = fontMetrics().height();
  const int lines = static_cast<int>(entries_.size());
  return QSize(2 * kMargin + line + kSpacing + text_width,
               2 * kMargin + lines * line + std::max(lines - 1, 0) * kLineGap);
}

void ColourLegend::place() {
  resize(sizeHint());
  move(kMargin, parentWidget()->height() - height() - kMargin);
  raise();
}

bool ColourLegend::eventFilter(QObject* watched, QEvent* event) {
  if (watched == parentWidget() && event->type() == QEvent::Resize) place();
  return QWidget::eventFilter(watched, event);
}

void ColourLegend::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(20, 22, 26, 190));
  painter.drawRoundedRect(rect(), 5, 5);
  for (int k = 0; k < static_cast<int>(entries_.size()); ++k) {
    const QRect swatch = swatchRect(k);
    painter.setPen(Qt::NoPen);
    painter.setBrush(entries_[k].colour);
    painter.drawRect(swatch);
    painter.setPen(QColor(235, 235, 235));
    painter.drawText(QRect(swatch.right() + 1 + kSpacing, swatch.top(), width(), swatch.height()),
                     Qt::AlignLeft | Qt::AlignVCenter, entries_[k].text);
  }
}

}  // namespace garment::ui
