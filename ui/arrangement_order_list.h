#pragma once
// The arrangement order: pieces in the order the session arranges them. The user drags a piece to
// another place; the list then emits the new order for the session to re-run from the first changed
// position. Drops are handled here (not by QListWidget's internal move) so that a drop carries the
// dragged row in its own MIME type and the same code path serves the mouse and the tests. Each row
// says which batch arranged its piece (the seed, batch 1, …; nothing while it waits), and the
// batches are shaded in turn, so that their boundaries show.

#include <QList>
#include <QListWidget>
#include <QStringList>
#include <vector>

namespace garment::ui {

class ArrangementOrderList : public QListWidget {
  Q_OBJECT
 public:
  static constexpr const char* kMimeType = "application/x-garment-studio-order-row";

  explicit ArrangementOrderList(QWidget* parent = nullptr);

  // pieces: piece indices in arrangement order; names: every piece's name, by piece index.
  // Does not emit orderChanged.
  void setOrder(const std::vector<int>& pieces, const QStringList& names);
  QList<int> order() const;
  // The batch of each row: 0 for the seed, k for batch k, -1 for a piece not arranged yet.
  // Rows beyond `batches` wait. Cleared by setOrder.
  void setBatches(const std::vector<int>& batches);
  int batchOfRow(int row) const;  // -1 for a waiting piece or a row out of range
  // Selects the row of the first of `pieces` (none if empty); does not emit orderChanged.
  void selectPieces(const QList<int>& pieces);
  QList<int> selectedPieces() const;
  // A drag from this list is in progress (the session should not refill the list under it).
  bool dragging() const { return state() == QAbstractItemView::DraggingState; }

  // Moves the item at `from` so that it ends up before the item now at `to` (to == count() moves
  // it last), as a drop does. Emits orderChanged when the order changed.
  void movePiece(int from, int to);
  // The row a drop at this viewport position lands before.
  int dropRow(const QPoint& viewport_position) const;

 signals:
  void orderChanged(const QList<int>& order);

 protected:
  QStringList mimeTypes() const override;
  QMimeData* mimeData(const QList<QListWidgetItem*>& items) const override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dragMoveEvent(QDragMoveEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void renumber();  // row numbers and batch labels
};

}  // namespace garment::ui
