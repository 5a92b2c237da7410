#pragma once
// The seeding classifier's verdict as a table: one row per classified piece (a piece, or strips
// the waist merge joined), its class, whether it was chosen as the seed, and the probability of
// each class. Plain data in (class names and indices, not the classifier's types), so that the
// table shows whatever classes the classifier has.

#include <QAbstractTableModel>
#include <QStringList>
#include <string>
#include <vector>

namespace garment::ui {

struct PieceClassification {
  std::string piece;                  // the piece's name, or the merged pieces' names joined by '+'
  int predicted = 0;                  // index into the class names
  std::vector<double> probabilities;  // per class, in class-name order, summing to 1
  bool seed = false;                  // part of the chosen seed
};

class ClassifierTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { PieceColumn, ClassColumn, SeedColumn, FirstProbabilityColumn };

  using QAbstractTableModel::QAbstractTableModel;

  // class_names: one per class (the engine's kSeedClassNames); one probability column each.
  void setClassifications(const QStringList& class_names, std::vector<PieceClassification> rows);
  const QStringList& classNames() const { return class_names_; }
  const std::vector<PieceClassification>& classifications() const { return rows_; }

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation,
                      int role = Qt::DisplayRole) const override;

 private:
  QStringList class_names_;
  std::vector<PieceClassification> rows_;
};

}  // namespace garment::ui
