#pragma once
// The 2D pattern view: every piece at its place on the pattern sheet (pattern_layout.h), filled
// with the colour of its arrangement state and labelled with its name. The sewing relationships of
// the selected pieces are drawn on top: both edges of each stitch highlighted in one colour and a
// few sewing pairs joined by dashed lines. Wheel zooms at the cursor, dragging pans, a click
// selects (Ctrl or Shift adds to the selection); dragging a selected piece drags the selection
// (piece_drag.h), to drop on a body location marker in the 3D view. A legend in the corner explains
// the fill colours. Labels are placed in the view, inside their pieces, so that none overlaps
// another or the legend or runs off the view; a label with no such place is hidden (the piece's
// tooltip still names it).

#include <QGraphicsPolygonItem>
#include <QGraphicsView>
#include <QList>
#include <memory>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "ui/piece_state.h"

namespace garment {
struct RegionGarments;  // seeding/scene.h
}

class QGraphicsPolygonItem;
class QGraphicsSimpleTextItem;

namespace garment::ui {

class ColourLegend;

class PatternView : public QGraphicsView {
  Q_OBJECT
 public:
  explicit PatternView(QWidget* parent = nullptr);

  // Shows a garment (nullptr clears the view). All pieces start waiting and unselected.
  void setGarment(std::shared_ptr<const Garment> garment);
  // One state per piece, in piece order; pieces past the end of the list are waiting.
  void setPieceStates(const std::vector<PieceState>& states);
  PieceState pieceState(int piece) const;

  // Selects without emitting pieceSelectionChanged (for mirroring another view's selection).
  void setSelectedPieces(const QList<int>& pieces);
  QList<int> selectedPieces() const { return selected_; }

  int pieceAt(const QPoint& view_position) const;  // -1 outside every piece
  // Where a piece's label sits, in view coordinates: a point inside the piece.
  QPoint pieceLabelPosition(int piece) const;
  // The rectangle a piece's label covers, in view coordinates; empty when the label is hidden.
  QRectF labelRect(int piece) const;
  // Stitches drawn for the current selection.
  int sewingHighlightCount() const { return sewing_highlight_count_; }
  // A quilt shown as its regions (the garment shown is quilt.region_garment): each of its pieces'
  // outlines drawn thin inside its region, where the quilting cut the cloth. setGarment clears
  // them.
  void setQuiltCells(const RegionGarments& quilt);
  // The cells drawn, one polygon per piece of the quilt, in scene coordinates.
  const std::vector<QGraphicsPolygonItem*>& quiltCells() const { return cell_items_; }
  // The outline drawn for a piece of the garment shown, in scene coordinates.
  QPolygonF pieceOutline(int piece) const { return piece_items_[piece]->polygon(); }
  ColourLegend* legend() const { return legend_; }

 public slots:
  void frameAll();

 signals:
  // The user changed the selection (click, Ctrl+click); not emitted by setSelectedPieces.
  void pieceSelectionChanged(const QList<int>& pieces);

 protected:
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void scrollContentsBy(int dx, int dy) override;

 private:
  QPointF scenePoint(int vertex) const;  // a garment vertex on the sheet
  QPointF labelAnchor(int piece, const QPointF& near) const;
  // Places every label at the first of its piece's candidate points where it overlaps nothing
  // placed before and stays in the view (large pieces first: they have the most room to give).
  void layoutLabels();
  void updatePieceAppearance(int piece);
  void rebuildSewingHighlights();

  std::shared_ptr<const Garment> garment_;
  std::vector<Eigen::Vector2d> offsets_;
  std::vector<QGraphicsPolygonItem*> piece_items_;
  std::vector<QGraphicsSimpleTextItem*> label_items_;
  // Per piece, scene points inside it where its label may sit, best first.
  std::vector<std::vector<QPointF>> label_candidates_;
  QRectF pieces_rect_;  // scene rectangle of all outlines
  std::vector<PieceState> states_;
  QList<int> selected_;
  std::vector<QGraphicsItem*> sewing_items_;
  std::vector<QGraphicsPolygonItem*> cell_items_;  // children of their regions' items
  int sewing_highlight_count_ = 0;
  ColourLegend* legend_ = nullptr;
  QPoint press_position_;
  bool piece_drag_armed_ = false;  // pressed on a selected piece: moving drags the selection
  bool framed_by_user_ = false;    // zoomed or panned: resizing keeps the user's view
};

}  // namespace garment::ui
