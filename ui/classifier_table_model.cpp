#include "ui/classifier_table_model.h"

#include <QFont>

namespace garment::ui {

void ClassifierTableModel::setClassifications(const QStringList& class_names,
                                              std::vector<PieceClassification> rows) {
  beginResetModel();
  class_names_ = class_names;
  rows_ = std::move(rows);
  endResetModel();
}

int ClassifierTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int ClassifierTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : FirstProbabilityColumn + static_cast<int>(class_names_.size());
}

QVariant ClassifierTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= static_cast<int>(rows_.size())) return {};
  const PieceClassification& row = rows_[index.row()];
  const int column = index.column();
  const int class_index = column - FirstProbabilityColumn;
  if (role == Qt::DisplayRole) {
    if (column == PieceColumn) return QString::fromStdString(row.piece);
    if (column == ClassColumn) return class_names_.value(row.predicted);
    if (column == SeedColumn) return row.seed ? tr("seed") : QString();
    if (class_index >= static_cast<int>(row.probabilities.size())) return QString();
    return QString::number(100.0 * row.probabilities[class_index], 'f', 1);
  }
  if (role == Qt::UserRole && class_index >= 0 &&
      class_index < static_cast<int>(row.probabilities.size()))
    return row.probabilities[class_index];
  if (role == Qt::TextAlignmentRole && class_index >= 0)
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  if (role == Qt::FontRole && (row.seed || class_index == row.predicted)) {
    QFont font;
    font.setBold(true);
    return font;
  }
  return {};
}

QVariant ClassifierTableModel::headerData(int section, Qt::Orientation orientation,
                                          int role) const {
  if (orientation != Qt::Horizontal) return {};
  if (role == Qt::DisplayRole) {
    if (section == PieceColumn) return tr("piece");
    if (section == ClassColumn) return tr("class");
    if (section == SeedColumn) return tr("seed");
    return class_names_.value(section - FirstProbabilityColumn) + " %";
  }
  if (role == Qt::ToolTipRole && section >= FirstProbabilityColumn)
    return tr("probability of this class, in percent");
  return {};
}

}  // namespace garment::ui
