#pragma once
// The Quality panel: the garment's quality verdict once an arrangement has ended, one row per
// failure with its kind, the pieces involved and the verdict's message (which carries the
// numbers), a design that cannot fit first with both lengths. Clicking a row asks for its pieces
// to be selected; the window selects them in both views. "Fix automatically" asks for the
// recovery (recovery/recovery.h); its attempts are listed as they end, the one shown in bold, and
// activating one (double-click, Enter) asks for its garment. quality_rows() and attempt_rows() are
// the panel's content as plain data, testable without a window.

#include <QList>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <optional>
#include <vector>

#include "engine/quality/verdict.h"
#include "engine/recovery/cannot_fit.h"
#include "engine/recovery/recovery.h"

class QLabel;
class QPushButton;
class QTreeWidget;

namespace garment::ui {

// One failure of a verdict as the panel lists it.
struct QualityRow {
  QString kind;     // failure_kind_name: "self_crossing", "strain", ...
  QString message;  // the verdict's line, with its numbers
  QList<int> pieces;
  QStringList piece_names;
};

// The failures of `verdict` in its order, after a row "cannot_fit" for `cannot_fit` when given.
// piece_names: the garment's, in piece order; a piece without a name (a verdict of another
// garment) is named by its index.
std::vector<QualityRow> quality_rows(const QualityVerdict& verdict, const QStringList& piece_names,
                                     const std::optional<CannotFit>& cannot_fit = std::nullopt);

// One attempt of a fix as the panel lists it.
struct AttemptRow {
  QString action;  // "first pass", "remesh", ... with the reason after a colon when there is one
  QString result;  // "clean", or the failure kinds
  QString work;    // the attempt's own solver work, millions
  QString seconds;
  bool shown = false;  // its garment is the one in the views
};

// The attempts in their order; `shown` is the index of the one shown (-1: none).
std::vector<AttemptRow> attempt_rows(const std::vector<AttemptRecord>& attempts, int shown);

class QualityPanel : public QWidget {
  Q_OBJECT
 public:
  enum Column { KindColumn, PiecesColumn, MessageColumn };

  explicit QualityPanel(QWidget* parent = nullptr);

  // nullopt: nothing judged (no arrangement has ended, or it was reset).
  void setVerdict(const std::optional<QualityVerdict>& verdict, const QStringList& piece_names,
                  const std::optional<CannotFit>& cannot_fit = std::nullopt);
  // The last fix's attempts (empty: none since the garment last changed), the one shown, and
  // whether the fix is still running.
  void setAttempts(const std::vector<AttemptRecord>& attempts, int shown, bool fixing);
  bool judged() const { return judged_; }
  const std::vector<QualityRow>& rows() const { return rows_; }
  const std::vector<AttemptRow>& attemptRows() const { return attempt_rows_; }
  QString summaryText() const;
  QTreeWidget* failureList() const { return failures_; }
  QTreeWidget* attemptList() const { return attempts_; }
  QPushButton* fixButton() const { return fix_; }

 signals:
  // The user chose a failure: its pieces.
  void piecesChosen(const QList<int>& pieces);
  void fixRequested();
  // The user chose the garment of attempt `index` (of the attempts set).
  void attemptChosen(int index);

 private:
  void choose(int row);
  void updateFixButton();

  bool judged_ = false;
  bool cannot_fit_ = false;
  bool fixing_ = false;
  std::vector<QualityRow> rows_;
  std::vector<AttemptRow> attempt_rows_;
  QLabel* summary_ = nullptr;
  QTreeWidget* failures_ = nullptr;
  QPushButton* fix_ = nullptr;
  QTreeWidget* attempts_ = nullptr;
};

}  // namespace garment::ui
