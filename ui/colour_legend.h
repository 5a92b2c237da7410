#pragma once
// A small legend drawn over a view: one colour swatch and one line of text per entry, on a
// translucent panel kept in the bottom-left corner of its parent. Clicks go through to the view.
// Hidden while it has no entries.

#include <QColor>
#include <QList>
#include <QString>
#include <QWidget>

namespace garment::ui {

struct LegendEntry {
  QColor colour;
  QString text;
  bool operator==(const LegendEntry& other) const = default;
};

class ColourLegend : public QWidget {
  Q_OBJECT
 public:
  // parent: the view it is drawn over (required: the legend follows its size).
  explicit ColourLegend(QWidget* parent);

  void setEntries(const QList<LegendEntry>& entries);
  const QList<LegendEntry>& entries() const { return entries_; }
  // The swatch of an entry, in the legend's coordinates.
  QRect swatchRect(int entry) const;

  QSize sizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void place();

  QList<LegendEntry> entries_;
};

}  // namespace garment::ui
