#include "ui/quality_panel.h"

#include <QFont>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace garment::ui {

namespace {

QualityRow make_row(QString kind, const std::string& message, const std::vector<int>& pieces,
                    const QStringList& piece_names) {
  QualityRow row;
  row.kind = std::move(kind);
  row.message = QString::fromStdString(message);
  for (int piece : pieces) {
    row.pieces << piece;
    row.piece_names << (piece >= 0 && piece < piece_names.size()
                            ? piece_names[piece]
                            : QObject::tr("piece %1").arg(piece));
  }
  return row;
}

}  // namespace

std::vector<QualityRow> quality_rows(const QualityVerdict& verdict, const QStringList& piece_names,
                                     const std::optional<CannotFit>& cannot_fit) {
  std::vector<QualityRow> rows;
  rows.reserve(verdict.failures.size() + 1);
  if (cannot_fit)
    rows.push_back(make_row(QStringLiteral("cannot_fit"), cannot_fit->message, cannot_fit->pieces,
                            piece_names));
  for (const QualityFailure& failure : verdict.failures) {
    const std::string_view kind = failure_kind_name(failure.kind);
    rows.push_back(make_row(QString::fromUtf8(kind.data(), static_cast<qsizetype>(kind.size())),
                            failure.message, failure.pieces, piece_names));
  }
  return rows;
}

std::vector<AttemptRow> attempt_rows(const std::vector<AttemptRecord>& attempts, int shown) {
  std::vector<AttemptRow> rows;
  for (std::size_t i = 0; i < attempts.size(); ++i) {
    const AttemptRecord& attempt = attempts[i];
    AttemptRow row;
    row.action = QString::fromStdString(attempt.action);
    if (!attempt.reason.empty()) row.action += ": " + QString::fromStdString(attempt.reason);
    QStringList kinds;
    for (const QualityFailure& failure : attempt.verdict.failures) {
      const std::string_view kind = failure_kind_name(failure.kind);
      kinds << QString::fromUtf8(kind.data(), static_cast<qsizetype>(kind.size()));
    }
    row.result = kinds.isEmpty() ? QObject::tr("clean") : kinds.join(", ");
    row.work = QString::number(attempt.work / 1e6, 'f', 1);
    row.seconds = QString::number(attempt.seconds, 'f', 1);
    row.shown = static_cast<int>(i) == shown;
    rows.push_back(std::move(row));
  }
  return rows;
}

QualityPanel::QualityPanel(QWidget* parent) : QWidget(parent) {
  setObjectName("quality_panel");
  summary_ = new QLabel(this);
  summary_->setObjectName("quality_summary");
  summary_->setWordWrap(true);
  failures_ = new QTreeWidget(this);
  failures_->setObjectName("quality_failures");
  failures_->setColumnCount(3);
  failures_->setHeaderLabels({tr("Problem"), tr("Pieces"), tr("Details")});
  failures_->setRootIsDecorated(false);
  failures_->setSelectionMode(QAbstractItemView::SingleSelection);
  failures_->header()->setSectionResizeMode(KindColumn, QHeaderView::ResizeToContents);
  failures_->setToolTip(tr("Click a problem to select its pieces in both views"));
  connect(failures_, &QTreeWidget::itemClicked, this,
          [this](QTreeWidgetItem* item) { choose(failures_->indexOfTopLevelItem(item)); });
  // The keyboard's way to the same: Enter on the current row.
  connect(failures_, &QTreeWidget::itemActivated, this,
          [this](QTreeWidgetItem* item) { choose(failures_->indexOfTopLevelItem(item)); });
  fix_ = new QPushButton(tr("Fix automatically"), this);
  fix_->setObjectName("fix_automatically");
  fix_->setToolTip(
      tr("Arrange the garment again with diagnosed corrections (another mesh, order or seed, a "
         "longer settle) and keep the best; Stop ends it early"));
  connect(fix_, &QPushButton::clicked, this, &QualityPanel::fixRequested);
  attempts_ = new QTreeWidget(this);
  attempts_->setObjectName("quality_attempts");
  attempts_->setColumnCount(4);
  attempts_->setHeaderLabels({tr("Attempt"), tr("Result"), tr("Work (M)"), tr("Time (s)")});
  attempts_->setRootIsDecorated(false);
  attempts_->setSelectionMode(QAbstractItemView::SingleSelection);
  attempts_->setToolTip(tr("Double-click an attempt (or press Enter) to show its garment"));
  connect(attempts_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
    const int index = attempts_->indexOfTopLevelItem(item);
    if (index >= 0 && !fixing_) Q_EMIT attemptChosen(index);
  });
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(summary_);
  layout->addWidget(failures_, 2);
  layout->addWidget(fix_);
  layout->addWidget(attempts_, 1);
  setVerdict(std::nullopt, {});
  setAttempts({}, -1, false);
}

void QualityPanel::setAttempts(const std::vector<AttemptRecord>& attempts, int shown, bool fixing) {
  fixing_ = fixing;
  attempt_rows_ = attempt_rows(attempts, shown);
  attempts_->clear();
  for (const AttemptRow& row : attempt_rows_) {
    auto* item = new QTreeWidgetItem(attempts_, {row.action, row.result, row.work, row.seconds});
    item->setToolTip(0, row.action);
    if (row.shown) {
      QFont bold = item->font(0);
      bold.setBold(true);
      for (int column = 0; column < attempts_->columnCount(); ++column)
        item->setFont(column, bold);
    }
  }
  attempts_->setVisible(!attempt_rows_.empty());
  summary_->setText(summaryText());
  updateFixButton();
}

void QualityPanel::updateFixButton() {
  // Once per garment: a fix keeps the best of its attempts, and another from there would try
  // the same actions again.
  fix_->setEnabled(judged_ && !rows_.empty() && !cannot_fit_ && !fixing_ && attempt_rows_.empty());
  fix_->setText(fixing_ ? tr("Fixing… (Stop ends it)") : tr("Fix automatically"));
  fix_->setVisible(judged_ && !rows_.empty());
}

void QualityPanel::setVerdict(const std::optional<QualityVerdict>& verdict,
                              const QStringList& piece_names,
                              const std::optional<CannotFit>& cannot_fit) {
  judged_ = verdict.has_value();
  cannot_fit_ = judged_ && cannot_fit.has_value();
  rows_ = verdict ? quality_rows(*verdict, piece_names, cannot_fit) : std::vector<QualityRow>{};
  failures_->clear();
  for (const QualityRow& row : rows_) {
    auto* item =
        new QTreeWidgetItem(failures_, {row.kind, row.piece_names.join(", "), row.message});
    // The message is long: whole in the tooltip whatever the column's width.
    for (int column = 0; column < failures_->columnCount(); ++column)
      item->setToolTip(column, row.message);
  }
  summary_->setText(summaryText());
  updateFixButton();
}

QString QualityPanel::summaryText() const {
  if (fixing_)
    return tr("Fixing automatically: %n attempt(s) after the first pass so far…", nullptr,
              static_cast<int>(attempt_rows_.size()) - 1);
  if (!judged_) return tr("No verdict yet: the garment is judged when the arrangement ends.");
  if (rows_.empty()) return tr("The garment passes every quality check.");
  if (cannot_fit_)
    return tr(
        "The design cannot fit this body (no arrangement can pass it); it fails %n quality "
        "check(s):",
        nullptr, static_cast<int>(rows_.size()) - 1);
  if (rows_.size() == 1) return tr("The garment fails 1 quality check:");
  return tr("The garment fails %1 quality checks:").arg(rows_.size());
}

void QualityPanel::choose(int row) {
  if (row < 0 || row >= static_cast<int>(rows_.size())) return;
  Q_EMIT piecesChosen(rows_[static_cast<std::size_t>(row)].pieces);
}

}  // namespace garment::ui
