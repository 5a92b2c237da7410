#include "ui/arrangement_order_list.h"

#include <QDropEvent>
#include <QMimeData>

namespace garment::ui {

namespace {
constexpr int kPieceRole = Qt::UserRole;
constexpr int kNameRole = Qt::UserRole + 1;
constexpr int kBatchRole = Qt::UserRole + 2;
}  // namespace

ArrangementOrderList::ArrangementOrderList(QWidget* parent) : QListWidget(parent) {
  setSelectionMode(QAbstractItemView::SingleSelection);
  setDragEnabled(true);
  setAcceptDrops(true);
  viewport()->setAcceptDrops(true);
  setDropIndicatorShown(true);
  setDragDropMode(QAbstractItemView::DragDrop);
  setDefaultDropAction(Qt::MoveAction);
}

void ArrangementOrderList::setOrder(const std::vector<int>& pieces, const QStringList& names) {
  clear();
  for (int piece : pieces) {
    auto* item = new QListWidgetItem(this);
    item->setData(kPieceRole, piece);
    item->setData(kNameRole,
                  piece >= 0 && piece < names.size() ? names[piece] : tr("piece %1").arg(piece));
    item->setData(kBatchRole, -1);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled);
  }
  renumber();
}

QList<int> ArrangementOrderList::order() const {
  QList<int> pieces;
  for (int row = 0; row < count(); ++row)
    pieces << item(row)->data(kPieceRole).toInt();
  return pieces;
}

void ArrangementOrderList::setBatches(const std::vector<int>& batches) {
  for (int row = 0; row < count(); ++row)
    item(row)->setData(kBatchRole, row < static_cast<int>(batches.size()) ? batches[row] : -1);
  renumber();
}

int ArrangementOrderList::batchOfRow(int row) const {
  return row >= 0 && row < count() ? item(row)->data(kBatchRole).toInt() : -1;
}

void ArrangementOrderList::selectPieces(const QList<int>& pieces) {
  const QSignalBlocker blocker(this);
  const QList<int> rows = order();
  const int row = pieces.isEmpty() ? -1 : static_cast<int>(rows.indexOf(pieces.front()));
  setCurrentRow(row);
  if (row < 0) clearSelection();
}

QList<int> ArrangementOrderList::selectedPieces() const {
  QList<int> pieces;
  for (const QListWidgetItem* selected : selectedItems())
    pieces << selected->data(kPieceRole).toInt();
  return pieces;
}

void ArrangementOrderList::renumber() {
  const QColor shade = palette().color(QPalette::AlternateBase);
  for (int row = 0; row < count(); ++row) {
    QListWidgetItem* row_item = item(row);
    const int batch = row_item->data(kBatchRole).toInt();
    QString text = QString("%1.  %2").arg(row + 1).arg(row_item->data(kNameRole).toString());
    if (batch == 0) text += tr("    seed");
    if (batch > 0) text += tr("    batch %1").arg(batch);
    row_item->setText(text);
    // Every other batch shaded: where the shading changes, a batch ends.
    row_item->setBackground(batch >= 0 && batch % 2 == 1 ? QBrush(shade) : QBrush());
  }
}

void ArrangementOrderList::movePiece(int from, int to) {
  if (from < 0 || from >= count() || to < 0 || to > count()) return;
  // Dropping an item just before or just after itself leaves it where it is.
  if (to == from || to == from + 1) return;
  QListWidgetItem* moved = takeItem(from);
  const int insert_row = to > from ? to - 1 : to;
  insertItem(insert_row, moved);
  setCurrentItem(moved);
  renumber();
  Q_EMIT orderChanged(order());
}

int ArrangementOrderList::dropRow(const QPoint& viewport_position) const {
  const QModelIndex index = indexAt(viewport_position);
  if (!index.isValid()) return count();
  const QRect rect = visualRect(index);
  return viewport_position.y() > rect.center().y() ? index.row() + 1 : index.row();
}

QStringList ArrangementOrderList::mimeTypes() const {
  return {kMimeType};
}

QMimeData* ArrangementOrderList::mimeData(const QList<QListWidgetItem*>& items) const {
  if (items.size() != 1) return nullptr;
  auto* data = new QMimeData;
  data->setData(kMimeType, QByteArray::number(row(items.front())));
  return data;
}

void ArrangementOrderList::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasFormat(kMimeType))
    event->acceptProposedAction();
  else
    event->ignore();
}

void ArrangementOrderList::dragMoveEvent(QDragMoveEvent* event) {
  // The base class draws the drop indicator; the format decides whether the drop is taken.
  QListWidget::dragMoveEvent(event);
  if (event->mimeData()->hasFormat(kMimeType)) {
    event->setDropAction(Qt::MoveAction);
    event->accept();
  } else {
    event->ignore();
  }
}

void ArrangementOrderList::dropEvent(QDropEvent* event) {
  if (!event->mimeData()->hasFormat(kMimeType)) {
    event->ignore();
    return;
  }
  bool ok = false;
  const int from = event->mimeData()->data(kMimeType).toInt(&ok);
  if (!ok) {
    event->ignore();
    return;
  }
  // Accepted as a copy so that the drag source does not delete the row it thinks was moved.
  event->setDropAction(Qt::CopyAction);
  event->accept();
  movePiece(from, dropRow(event->position().toPoint()));
  // Clears the drop indicator the base class drew.
  viewport()->update();
}

}  // namespace garment::ui
