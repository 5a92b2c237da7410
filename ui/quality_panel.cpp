#include "ui/quality_panel.h"

#include <QHeaderView>
#include <QLabel>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace garment::ui {

std::vector<QualityRow> quality_rows(const QualityVerdict& verdict,
                                     const QStringList& piece_names) {
  std::vector<QualityRow> rows;
  rows.reserve(verdict.failures.size());
  for (const QualityFailure& failure : verdict.failures) {
    QualityRow row;
    const std::string_view kind = failure_kind_name(failure.kind);
    row.kind = QString::fromUtf8(kind.data(), static_cast<qsizetype>(kind.size()));
    row.message = QString::fromStdString(failure.message);
    for (int piece : failure.pieces) {
      row.pieces << piece;
      row.piece_names << (piece >= 0 && piece < piece_names.size()
                              ? piece_names[piece]
                              : QObject::tr("piece %1").arg(piece));
    }
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
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(summary_);
  layout->addWidget(failures_, 1);
  setVerdict(std::nullopt, {});
}

void QualityPanel::setVerdict(const std::optional<QualityVerdict>& verdict,
                              const QStringList& piece_names) {
  judged_ = verdict.has_value();
  rows_ = verdict ? quality_rows(*verdict, piece_names) : std::vector<QualityRow>{};
  failures_->clear();
  for (const QualityRow& row : rows_) {
    auto* item =
        new QTreeWidgetItem(failures_, {row.kind, row.piece_names.join(", "), row.message});
    // The message is long: whole in the tooltip whatever the column's width.
    for (int column = 0; column < failures_->columnCount(); ++column)
      item->setToolTip(column, row.message);
  }
  summary_->setText(summaryText());
}

QString QualityPanel::summaryText() const {
  if (!judged_) return tr("No verdict yet: the garment is judged when the arrangement ends.");
  if (rows_.empty()) return tr("The garment passes every quality check.");
  if (rows_.size() == 1) return tr("The garment fails 1 quality check:");
  return tr("The garment fails %1 quality checks:").arg(rows_.size());
}

void QualityPanel::choose(int row) {
  if (row < 0 || row >= static_cast<int>(rows_.size())) return;
  Q_EMIT piecesChosen(rows_[static_cast<std::size_t>(row)].pieces);
}

}  // namespace garment::ui
