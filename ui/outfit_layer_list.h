#pragma once
// The outfit's layers (issue "Complex garments"): the garments open in the editor, innermost at
// the top, as `garment-init run inner.json outer.json` takes them. The user adds a garment worn
// over the others, drags a garment to another layer or moves it inward / outward with the
// buttons, and removes one; the list emits what was asked and the window rebuilds the outfit
// (main_window.h). Below the list, once an arrangement is judged: the crossings between garments.

#include <QList>
#include <QStringList>
#include <QWidget>

class QAction;
class QLabel;
class QListWidget;
class QPushButton;

namespace garment::ui {

class OutfitLayerList : public QWidget {
  Q_OBJECT
 public:
  // add_garment: the window's File › Add garment… action, also on a button here.
  explicit OutfitLayerList(QAction* add_garment, QWidget* parent = nullptr);

  // The garments' names, innermost first. Does not emit; clears the crossings shown.
  void setLayers(const QStringList& names);
  QStringList layers() const;
  // What the arrangement's verdict says of the crossings between garments: a line per pair that
  // crosses, "no crossing between garments" when none does, nothing when not judged.
  void setCrossingsBetweenGarments(const QStringList& lines);
  QString crossingsText() const;

  // Moves the garment at layer `from` to layer `to` (0 innermost), as a drag or the buttons do.
  // Emits orderChanged when the order changed.
  void moveLayer(int from, int to);
  // Asks for the garment at `layer` to be removed (never the last one).
  void removeLayer(int layer);

  QListWidget* list() const { return list_; }
  QPushButton* inwardButton() const { return inward_; }
  QPushButton* outwardButton() const { return outward_; }
  QPushButton* removeButton() const { return remove_; }

 signals:
  // order[i]: the layer (before the change) now at layer i.
  void orderChanged(const QList<int>& order);
  void removeRequested(int layer);

 private:
  void showLayers(const QStringList& names);
  void updateButtons();
  // After a drag inside the list: the rows' original layers, in their new order.
  void emitDraggedOrder();

  QListWidget* list_ = nullptr;
  QPushButton* inward_ = nullptr;
  QPushButton* outward_ = nullptr;
  QPushButton* remove_ = nullptr;
  QLabel* crossings_ = nullptr;
  QStringList names_;
};

}  // namespace garment::ui
