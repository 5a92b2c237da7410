#include "ui/outfit_layer_list.h"

#include <QAbstractItemModel>
#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace garment::ui {

namespace {

constexpr int kLayerRole = Qt::UserRole;  // the row's layer when the list was last filled

}  // namespace

OutfitLayerList::OutfitLayerList(QAction* add_garment, QWidget* parent) : QWidget(parent) {
  list_ = new QListWidget(this);
  list_->setObjectName("outfit_layers");
  list_->setSelectionMode(QAbstractItemView::SingleSelection);
  list_->setDragDropMode(QAbstractItemView::InternalMove);
  list_->setDefaultDropAction(Qt::MoveAction);
  list_->setToolTip(tr("The garments worn, innermost first: drag one to another layer"));
  // A drop has moved the row by the time the model says so; the window then rebuilds the outfit,
  // which refills the list (queued: not while the view is still finishing its drop).
  connect(list_->model(), &QAbstractItemModel::rowsMoved, this, &OutfitLayerList::emitDraggedOrder,
          Qt::QueuedConnection);
  connect(list_, &QListWidget::currentRowChanged, this, &OutfitLayerList::updateButtons);

  auto* add = new QToolButton(this);
  add->setDefaultAction(add_garment);
  add->setToolButtonStyle(Qt::ToolButtonTextOnly);
  inward_ = new QPushButton(tr("Inward"), this);
  inward_->setToolTip(tr("Wear the chosen garment under the one inside it"));
  outward_ = new QPushButton(tr("Outward"), this);
  outward_->setToolTip(tr("Wear the chosen garment over the one outside it"));
  remove_ = new QPushButton(tr("Remove"), this);
  connect(inward_, &QPushButton::clicked, this, [this] {
    const int row = list_->currentRow();
    moveLayer(row, row - 1);
  });
  connect(outward_, &QPushButton::clicked, this, [this] {
    const int row = list_->currentRow();
    moveLayer(row, row + 1);
  });
  connect(remove_, &QPushButton::clicked, this, [this] { removeLayer(list_->currentRow()); });

  crossings_ = new QLabel(this);
  crossings_->setObjectName("outfit_crossings");
  crossings_->setWordWrap(true);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(add);
  buttons->addWidget(inward_);
  buttons->addWidget(outward_);
  buttons->addWidget(remove_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(list_);
  layout->addLayout(buttons);
  layout->addWidget(crossings_);
  updateButtons();
}

void OutfitLayerList::setLayers(const QStringList& names) {
  names_ = names;
  showLayers(names);
  crossings_->clear();
}

QStringList OutfitLayerList::layers() const {
  return names_;
}

void OutfitLayerList::setCrossingsBetweenGarments(const QStringList& lines) {
  crossings_->setText(lines.join('\n'));
}

QString OutfitLayerList::crossingsText() const {
  return crossings_->text();
}

void OutfitLayerList::showLayers(const QStringList& names) {
  const QSignalBlocker blocker(list_);
  const int current = list_->currentRow();
  list_->clear();
  for (int layer = 0; layer < names.size(); ++layer) {
    QString text = tr("%1. %2").arg(layer + 1).arg(names[layer]);
    if (names.size() > 1 && layer == 0) text += tr("  (innermost)");
    if (names.size() > 1 && layer == names.size() - 1) text += tr("  (outermost)");
    auto* item = new QListWidgetItem(text, list_);
    item->setData(kLayerRole, layer);
  }
  list_->setCurrentRow(std::min(current, static_cast<int>(names.size()) - 1));
  updateButtons();
}

void OutfitLayerList::moveLayer(int from, int to) {
  const int count = static_cast<int>(names_.size());
  if (from < 0 || from >= count || to < 0 || to >= count || from == to) return;
  QList<int> order;
  for (int layer = 0; layer < count; ++layer)
    order << layer;
  order.move(from, to);
  list_->setCurrentRow(to);
  Q_EMIT orderChanged(order);
}

void OutfitLayerList::removeLayer(int layer) {
  if (layer < 0 || layer >= names_.size() || names_.size() < 2) return;
  Q_EMIT removeRequested(layer);
}

void OutfitLayerList::emitDraggedOrder() {
  QList<int> order;
  bool changed = false;
  for (int row = 0; row < list_->count(); ++row) {
    order << list_->item(row)->data(kLayerRole).toInt();
    changed = changed || order.back() != row;
  }
  if (changed)
    Q_EMIT orderChanged(order);
  else
    showLayers(names_);
}

void OutfitLayerList::updateButtons() {
  const int row = list_->currentRow();
  const int count = list_->count();
  inward_->setEnabled(row > 0);
  outward_->setEnabled(row >= 0 && row + 1 < count);
  remove_->setEnabled(row >= 0 && count > 1);
}

}  // namespace garment::ui
