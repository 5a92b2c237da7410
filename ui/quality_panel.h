#pragma once
// The Quality panel: the garment's quality verdict once an arrangement has ended, one row per
// failure with its kind, the pieces involved and the verdict's message (which carries the
// numbers). Clicking a row asks for its pieces to be selected; the window selects them in both
// views. quality_rows() is the panel's content as plain data, testable without a window.

#include <QList>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <optional>
#include <vector>

#include "engine/quality/verdict.h"

class QLabel;
class QTreeWidget;

namespace garment::ui {

// One failure of a verdict as the panel lists it.
struct QualityRow {
  QString kind;     // failure_kind_name: "self_crossing", "strain", ...
  QString message;  // the verdict's line, with its numbers
  QList<int> pieces;
  QStringList piece_names;
};

// The failures of `verdict` in its order. piece_names: the garment's, in piece order; a piece
// without a name (a verdict of another garment) is named by its index.
std::vector<QualityRow> quality_rows(const QualityVerdict& verdict, const QStringList& piece_names);

class QualityPanel : public QWidget {
  Q_OBJECT
 public:
  enum Column { KindColumn, PiecesColumn, MessageColumn };

  explicit QualityPanel(QWidget* parent = nullptr);

  // nullopt: nothing judged (no arrangement has ended, or it was reset).
  void setVerdict(const std::optional<QualityVerdict>& verdict, const QStringList& piece_names);
  bool judged() const { return judged_; }
  const std::vector<QualityRow>& rows() const { return rows_; }
  QString summaryText() const;
  QTreeWidget* failureList() const { return failures_; }

 signals:
  // The user chose a failure: its pieces.
  void piecesChosen(const QList<int>& pieces);

 private:
  void choose(int row);

  bool judged_ = false;
  std::vector<QualityRow> rows_;
  QLabel* summary_ = nullptr;
  QTreeWidget* failures_ = nullptr;
};

}  // namespace garment::ui
