#include "ui/pattern_view.h"

#include <QApplication>
#include <QDrag>
#include <QGraphicsPolygonItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QMouseEvent>
#include <QScrollBar>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/pattern/region_transfer.h"
#include "engine/seeding/scene.h"
#include "ui/colour_legend.h"
#include "ui/pattern_layout.h"
#include "ui/piece_drag.h"

namespace garment::ui {

namespace {

constexpr int kPieceKey = 0;                  // QGraphicsItem::data key holding the piece index
constexpr std::size_t kLabelCandidates = 64;  // places tried per label

// Distinct colours for the stitches of the selection.
const QColor kStitchColours[] = {QColor(31, 119, 180),  QColor(214, 39, 40),  QColor(44, 160, 44),
                                 QColor(148, 103, 189), QColor(23, 190, 207), QColor(227, 119, 194),
                                 QColor(140, 86, 75),   QColor(188, 189, 34)};

// A piece's outline. Its shape (what clicks hit) is the polygon alone: the default adds the pen's
// width in scene units, which for a cosmetic pen on a sheet measured in metres covers everything.
class PieceItem : public QGraphicsPolygonItem {
 public:
  using QGraphicsPolygonItem::QGraphicsPolygonItem;
  QPainterPath shape() const override {
    QPainterPath path;
    path.addPolygon(polygon());
    path.closeSubpath();
    return path;
  }
};

}  // namespace

PatternView::PatternView(QWidget* parent) : QGraphicsView(parent) {
  setScene(new QGraphicsScene(this));
  setRenderHint(QPainter::Antialiasing);
  setDragMode(QGraphicsView::ScrollHandDrag);
  setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
  setResizeAnchor(QGraphicsView::AnchorViewCenter);
  setBackgroundBrush(QColor(250, 250, 247));
  setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  // Files dropped here go to the main window.
  setAcceptDrops(false);
  viewport()->setAcceptDrops(false);
  // The fill colours of the arrangement states, always in view.
  legend_ = new ColourLegend(this);
  QList<LegendEntry> entries;
  for (PieceState state :
       {PieceState::Waiting, PieceState::InBatch, PieceState::Arranged, PieceState::Seed})
    entries.append({piece_state_colour(state), piece_state_name(state)});
  legend_->setEntries(entries);
}

void PatternView::setGarment(std::shared_ptr<const Garment> garment) {
  scene()->clear();
  piece_items_.clear();
  cell_items_.clear();
  label_items_.clear();
  label_candidates_.clear();
  pieces_rect_ = QRectF();
  sewing_items_.clear();
  sewing_highlight_count_ = 0;
  selected_.clear();
  states_.clear();
  garment_ = std::move(garment);
  if (!garment_) return;

  offsets_ = pattern_layout_offsets(*garment_);
  const int piece_count = static_cast<int>(garment_->pieces.size());
  states_.assign(piece_count, PieceState::Waiting);
  for (int p = 0; p < piece_count; ++p) {
    const Piece& piece = garment_->pieces[p];
    QPolygonF outline;
    for (int vertex : piece.outline)
      outline << scenePoint(vertex);
    auto* item = new PieceItem(outline);
    scene()->addItem(item);
    item->setData(kPieceKey, p);
    item->setToolTip(QString::fromStdString(piece.name));
    auto* label = new QGraphicsSimpleTextItem(QString::fromStdString(piece.name), item);
    label->setFlag(QGraphicsItem::ItemIgnoresTransformations);
    const QRectF text = label->boundingRect();
    label->setTransform(QTransform::fromTranslate(-text.width() / 2, -text.height() / 2));
    label->setPos(labelAnchor(p, outline.boundingRect().center()));
    // The centroids of the piece's triangles, nearest the outline's centre first, at most
    // kLabelCandidates of them spread over the piece.
    std::vector<QPointF> centroids;
    for (int t = piece.first_triangle; t < piece.first_triangle + piece.triangle_count; ++t)
      centroids.push_back((scenePoint(garment_->triangles(t, 0)) +
                           scenePoint(garment_->triangles(t, 1)) +
                           scenePoint(garment_->triangles(t, 2))) /
                          3.0);
    const QPointF centre = label->pos();
    std::sort(centroids.begin(), centroids.end(), [&](const QPointF& a, const QPointF& b) {
      return QLineF(a, centre).length() < QLineF(b, centre).length();
    });
    std::vector<QPointF> candidates;
    const std::size_t stride = std::max<std::size_t>(1, centroids.size() / kLabelCandidates);
    for (std::size_t i = 0; i < centroids.size(); i += stride)
      candidates.push_back(centroids[i]);
    label_candidates_.push_back(std::move(candidates));
    piece_items_.push_back(item);
    label_items_.push_back(label);
    updatePieceAppearance(p);
  }
  // Labels keep their size in pixels whatever the zoom, so only the outlines measure the sheet.
  pieces_rect_ = QRectF();
  for (QGraphicsPolygonItem* item : piece_items_)
    pieces_rect_ = pieces_rect_.united(item->polygon().boundingRect());
  // A margin around the sheet leaves room to pan past its edges.
  scene()->setSceneRect(pieces_rect_.adjusted(-2.0, -2.0, 2.0, 2.0));
  framed_by_user_ = false;
  frameAll();
}

void PatternView::setQuiltCells(const RegionGarments& quilt) {
  for (QGraphicsPolygonItem* item : cell_items_)
    delete item;
  cell_items_.clear();
  if (!garment_ || quilt.region_garment != garment_) return;
  // The regions' rest positions carried to the pieces as the arrangement's positions would be:
  // each piece vertex lands at its place in its region's rest frame.
  Eigen::MatrixX3d region_rest = Eigen::MatrixX3d::Zero(garment_->vertex_count(), 3);
  region_rest.leftCols<2>() = garment_->rest_positions;
  const Eigen::MatrixX3d cells =
      transfer_region_positions(*quilt.pieces, *garment_, quilt.region_of_panel, region_rest);
  QPen pen(QColor(60, 60, 60, 160), 0.8, Qt::DotLine);
  pen.setCosmetic(true);
  for (std::size_t p = 0; p < quilt.pieces->pieces.size(); ++p) {
    const int region = quilt.region_of_panel[p];
    QPolygonF outline;
    for (int vertex : quilt.pieces->pieces[p].outline) {
      const Eigen::Vector2d point = cells.row(vertex).head<2>().transpose() + offsets_[region];
      outline << QPointF(point.x(), -point.y());  // scene y points down
    }
    // A child of its region's outline: drawn over its fill, and no piece of its own to click.
    auto* item = new QGraphicsPolygonItem(outline, piece_items_[region]);
    item->setPen(pen);
    cell_items_.push_back(item);
  }
}

QPointF PatternView::labelAnchor(int piece_index, const QPointF& near) const {
  // The centroid of a triangle of the piece is inside the piece, also for L-shaped outlines whose
  // bounding box centre is not.
  const Piece& piece = garment_->pieces[piece_index];
  QPointF best = near;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int t = piece.first_triangle; t < piece.first_triangle + piece.triangle_count; ++t) {
    const QPointF centroid =
        (scenePoint(garment_->triangles(t, 0)) + scenePoint(garment_->triangles(t, 1)) +
         scenePoint(garment_->triangles(t, 2))) /
        3.0;
    const double distance = QLineF(centroid, near).length();
    if (distance < best_distance) {
      best_distance = distance;
      best = centroid;
    }
  }
  return best;
}

QPointF PatternView::scenePoint(int vertex) const {
  const int piece = garment_->vertex_piece(vertex);
  const Eigen::Vector2d p = garment_->rest_positions.row(vertex).transpose() + offsets_[piece];
  return QPointF(p.x(), -p.y());  // scene y points down
}

void PatternView::setPieceStates(const std::vector<PieceState>& states) {
  for (int p = 0; p < static_cast<int>(states_.size()); ++p) {
    const PieceState state = p < static_cast<int>(states.size()) ? states[p] : PieceState::Waiting;
    if (states_[p] == state) continue;
    states_[p] = state;
    updatePieceAppearance(p);
  }
}

PieceState PatternView::pieceState(int piece) const {
  if (piece < 0 || piece >= static_cast<int>(states_.size())) return PieceState::Waiting;
  return states_[piece];
}

void PatternView::updatePieceAppearance(int piece) {
  QGraphicsPolygonItem* item = piece_items_[piece];
  const bool selected = selected_.contains(piece);
  QColor fill = piece_state_colour(states_[piece]);
  if (selected) fill = fill.lighter(112);
  item->setBrush(fill);
  QPen pen(selected ? QColor(15, 15, 15) : QColor(80, 80, 80), selected ? 2.5 : 1.0);
  pen.setCosmetic(true);
  pen.setJoinStyle(Qt::RoundJoin);
  item->setPen(pen);
  item->setZValue(selected ? 1 : 0);
  const QString state = piece_state_name(states_[piece]);
  item->setToolTip(QString::fromStdString(garment_->pieces[piece].name) + " — " + state);
}

void PatternView::setSelectedPieces(const QList<int>& pieces) {
  QList<int> valid;
  for (int piece : pieces)
    if (piece >= 0 && piece < static_cast<int>(piece_items_.size()) && !valid.contains(piece))
      valid << piece;
  if (valid == selected_) return;
  const QList<int> previous = selected_;
  selected_ = valid;
  for (int piece : previous)
    updatePieceAppearance(piece);
  for (int piece : selected_)
    updatePieceAppearance(piece);
  rebuildSewingHighlights();
}

void PatternView::rebuildSewingHighlights() {
  for (QGraphicsItem* item : sewing_items_) {
    scene()->removeItem(item);
    delete item;
  }
  sewing_items_.clear();
  sewing_highlight_count_ = 0;
  if (!garment_) return;

  int colour_index = 0;
  for (const StitchPairs& pairs : garment_->stitches) {
    const Stitch& stitch = garment_->pattern.stitches[pairs.stitch];
    if (!selected_.contains(stitch.a.panel) && !selected_.contains(stitch.b.panel)) continue;
    const QColor colour = kStitchColours[colour_index++ % std::size(kStitchColours)];
    for (const EdgeRef& side : {stitch.a, stitch.b}) {
      QPainterPath path;
      const std::vector<int>& vertices = garment_->pieces[side.panel].edge_vertices[side.edge];
      for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (i == 0)
          path.moveTo(scenePoint(vertices[i]));
        else
          path.lineTo(scenePoint(vertices[i]));
      }
      QPen pen(colour, 4.0);
      pen.setCosmetic(true);
      pen.setCapStyle(Qt::RoundCap);
      auto* item = scene()->addPath(path, pen);
      item->setZValue(2);
      sewing_items_.push_back(item);
    }
    // A few pairs (ends and middle) show which way the seam runs without hiding the pieces.
    QList<int> shown = {0, pairs.pair_count / 2, pairs.pair_count - 1};
    std::sort(shown.begin(), shown.end());
    shown.erase(std::unique(shown.begin(), shown.end()), shown.end());
    for (int k : shown) {
      if (k < 0 || k >= pairs.pair_count) continue;
      const int row = pairs.first_pair + k;
      QPen pen(colour, 1.2, Qt::DashLine);
      pen.setCosmetic(true);
      auto* line = scene()->addLine(QLineF(scenePoint(garment_->sewing_pairs(row, 0)),
                                           scenePoint(garment_->sewing_pairs(row, 1))),
                                    pen);
      line->setZValue(3);
      sewing_items_.push_back(line);
    }
    ++sewing_highlight_count_;
  }
}

int PatternView::pieceAt(const QPoint& view_position) const {
  // Labels and seam overlays carry no piece: only the outline polygons answer.
  for (QGraphicsItem* item : items(view_position)) {
    const QVariant piece = item->data(kPieceKey);
    if (piece.isValid()) return piece.toInt();
  }
  return -1;
}

QPoint PatternView::pieceLabelPosition(int piece) const {
  if (piece < 0 || piece >= static_cast<int>(piece_items_.size())) return {};
  return mapFromScene(label_items_[piece]->pos());
}

QRectF PatternView::labelRect(int piece) const {
  if (piece < 0 || piece >= static_cast<int>(label_items_.size()) ||
      !label_items_[piece]->isVisible())
    return {};
  // The label ignores the view's scale: its text measures pixels, centred on its position.
  const QSizeF size = label_items_[piece]->boundingRect().size();
  const QPointF centre = viewportTransform().map(label_items_[piece]->pos());
  return QRectF(centre - QPointF(size.width() / 2, size.height() / 2), size);
}

void PatternView::layoutLabels() {
  std::vector<int> order(label_items_.size());
  for (std::size_t p = 0; p < order.size(); ++p)
    order[p] = static_cast<int>(p);
  std::stable_sort(order.begin(), order.end(), [this](int a, int b) {
    return garment_->pieces[a].triangle_count > garment_->pieces[b].triangle_count;
  });
  const QRectF view(viewport()->rect());
  std::vector<QRectF> taken;
  if (legend_->isVisible())
    taken.push_back(QRectF(legend_->geometry()).translated(-QPointF(viewport()->pos())));
  for (int p : order) {
    QGraphicsSimpleTextItem* label = label_items_[p];
    const QSizeF size = label->boundingRect().size();
    bool placed = false;
    for (const QPointF& candidate : label_candidates_[p]) {
      const QPointF centre = viewportTransform().map(candidate);
      const QRectF rect(centre - QPointF(size.width() / 2, size.height() / 2), size);
      if (!view.contains(rect) ||
          std::any_of(taken.begin(), taken.end(),
                      [&rect](const QRectF& other) { return other.intersects(rect); }))
        continue;
      label->setPos(candidate);
      taken.push_back(rect);
      placed = true;
      break;
    }
    label->setVisible(placed);
  }
}

void PatternView::frameAll() {
  if (piece_items_.empty()) return;
  fitInView(pieces_rect_.adjusted(-0.05, -0.05, 0.05, 0.05), Qt::KeepAspectRatio);
  framed_by_user_ = false;
  layoutLabels();
}

void PatternView::resizeEvent(QResizeEvent* event) {
  QGraphicsView::resizeEvent(event);
  if (!framed_by_user_) frameAll();
  layoutLabels();
}

void PatternView::scrollContentsBy(int dx, int dy) {
  QGraphicsView::scrollContentsBy(dx, dy);
  layoutLabels();
}

void PatternView::wheelEvent(QWheelEvent* event) {
  const double factor = std::pow(1.0015, event->angleDelta().y());
  scale(factor, factor);
  framed_by_user_ = true;
  layoutLabels();
  event->accept();
}

void PatternView::mousePressEvent(QMouseEvent* event) {
  press_position_ = event->position().toPoint();
  // On a selected piece the left button drags the selection, not the sheet.
  piece_drag_armed_ = event->button() == Qt::LeftButton && event->modifiers() == Qt::NoModifier &&
                      selected_.contains(pieceAt(press_position_));
  if (piece_drag_armed_) {
    event->accept();
    return;
  }
  QGraphicsView::mousePressEvent(event);
}

void PatternView::mouseMoveEvent(QMouseEvent* event) {
  if (!piece_drag_armed_) {
    QGraphicsView::mouseMoveEvent(event);
    return;
  }
  if ((event->position().toPoint() - press_position_).manhattanLength() <
      QApplication::startDragDistance())
    return;
  piece_drag_armed_ = false;
  auto* drag = new QDrag(this);
  drag->setMimeData(piece_mime_data(selected_));
  drag->exec(Qt::CopyAction);
}

void PatternView::mouseReleaseEvent(QMouseEvent* event) {
  if (piece_drag_armed_) {
    // A click on a selected piece (moving would have dragged it): it selects as any click does.
    piece_drag_armed_ = false;
  } else {
    QGraphicsView::mouseReleaseEvent(event);
  }
  if (event->button() != Qt::LeftButton) return;
  const QPoint position = event->position().toPoint();
  if ((position - press_position_).manhattanLength() >= QApplication::startDragDistance()) {
    framed_by_user_ = true;  // that was a pan
    return;
  }
  const int piece = pieceAt(position);
  QList<int> selection;
  if (event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier)) {
    selection = selected_;
    if (piece >= 0 && !selection.removeOne(piece)) selection << piece;
  } else if (piece >= 0) {
    selection << piece;
  }
  if (selection == selected_) return;
  setSelectedPieces(selection);
  Q_EMIT pieceSelectionChanged(selected_);
}

}  // namespace garment::ui
