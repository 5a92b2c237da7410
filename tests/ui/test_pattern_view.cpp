// The pattern view: every piece on the sheet without overlap, front pieces above back pieces in
// reading order, state colours, click and Ctrl+click selection, the stitches of the selection
// drawn, zoom.

#include <QGraphicsPolygonItem>
#include <QSignalSpy>
#include <QtTest>
#include <filesystem>

#include "support/test_paths.h"
#include "tests/ui/ui_test_support.h"
#include "ui/pattern_layout.h"
#include "ui/pattern_view.h"

using namespace garment;

namespace {

QRectF piece_rect(const Garment& garment, const std::vector<Eigen::Vector2d>& offsets, int piece) {
  const Piece& p = garment.pieces[piece];
  const auto rest = garment.rest_positions.middleRows(p.first_vertex, p.vertex_count);
  const Eigen::Vector2d lower = rest.colwise().minCoeff().transpose() + offsets[piece];
  const Eigen::Vector2d upper = rest.colwise().maxCoeff().transpose() + offsets[piece];
  return QRectF(QPointF(lower.x(), lower.y()), QPointF(upper.x(), upper.y()));
}

QGraphicsPolygonItem* piece_item(ui::PatternView& view, int piece) {
  for (QGraphicsItem* item : view.scene()->items())
    if (item->data(0).isValid() && item->data(0).toInt() == piece)
      return dynamic_cast<QGraphicsPolygonItem*>(item);
  return nullptr;
}

}  // namespace

class PatternViewTest : public QObject {
  Q_OBJECT

 private:
  std::shared_ptr<const Garment> garment_;
  std::unique_ptr<ui::PatternView> view_;

 private slots:
  void initTestCase() { garment_ = test::demo_garment(); }

  void init() {
    view_ = std::make_unique<ui::PatternView>();
    view_->resize(640, 480);
    view_->show();
    QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
    view_->setGarment(garment_);
  }

  void cleanup() { view_.reset(); }

  void layoutNeverOverlapsPieces() {
    for (const auto& entry : std::filesystem::directory_iterator(test::test_data("patterns"))) {
      if (entry.path().extension() != ".json") continue;
      const Garment garment = build_garment(load_pattern(entry.path()));
      const auto offsets = ui::pattern_layout_offsets(garment);
      QCOMPARE(offsets.size(), garment.pieces.size());
      for (std::size_t a = 0; a < garment.pieces.size(); ++a)
        for (std::size_t b = a + 1; b < garment.pieces.size(); ++b)
          QVERIFY2(!piece_rect(garment, offsets, a).intersects(piece_rect(garment, offsets, b)),
                   qPrintable(QString("%1: %2 overlaps %3")
                                  .arg(entry.path().filename().c_str())
                                  .arg(garment.pieces[a].name.c_str())
                                  .arg(garment.pieces[b].name.c_str())));
    }
  }

  void frontAboveBackInReadingOrder() {
    const auto offsets = ui::pattern_layout_offsets(*garment_);
    auto rect = [&](const char* name) {
      return piece_rect(*garment_, offsets, garment_->pattern.panel_index(name));
    };
    // Front row above the back row.
    QVERIFY(rect("left_ftorso").bottom() > rect("left_btorso").top());
    QVERIFY(rect("right_ftorso").bottom() > rect("right_btorso").top());
    // Seen from the front the body's right is on the left; seen from behind, its left.
    QVERIFY(rect("right_ftorso").right() < rect("left_ftorso").left());
    QVERIFY(rect("left_ftorso").right() < rect("left_sleeve_f").left());
    QVERIFY(rect("left_btorso").right() < rect("right_btorso").left());
  }

  void everyPieceDrawnAndNamed() {
    for (int p = 0; p < static_cast<int>(garment_->pieces.size()); ++p) {
      QGraphicsPolygonItem* item = piece_item(*view_, p);
      QVERIFY(item);
      QCOMPARE(item->polygon().size(), static_cast<int>(garment_->pieces[p].outline.size()));
      QCOMPARE(view_->pieceAt(view_->pieceLabelPosition(p)), p);
      bool named = false;
      for (QGraphicsItem* child : item->childItems())
        if (auto* text = dynamic_cast<QGraphicsSimpleTextItem*>(child))
          named = text->text() == QString::fromStdString(garment_->pieces[p].name);
      QVERIFY(named);
    }
  }

  void statesColourPieces() {
    std::vector<ui::PieceState> states = {ui::PieceState::Seed, ui::PieceState::Arranged,
                                          ui::PieceState::InBatch};
    view_->setPieceStates(states);
    for (int p = 0; p < static_cast<int>(garment_->pieces.size()); ++p) {
      const ui::PieceState expected = p < 3 ? states[p] : ui::PieceState::Waiting;
      QCOMPARE(view_->pieceState(p), expected);
      QCOMPARE(piece_item(*view_, p)->brush().color(), ui::piece_state_colour(expected));
    }
    // The four states have four different colours.
    QSet<QRgb> colours;
    for (auto state : {ui::PieceState::Waiting, ui::PieceState::InBatch, ui::PieceState::Arranged,
                       ui::PieceState::Seed})
      colours.insert(ui::piece_state_colour(state).rgb());
    QCOMPARE(colours.size(), 4);
  }

  void clickSelectsAndDrawsStitches() {
    QSignalSpy selection(view_.get(), &ui::PatternView::pieceSelectionChanged);
    const int torso = garment_->pattern.panel_index("left_ftorso");
    QTest::mouseClick(view_->viewport(), Qt::LeftButton, Qt::NoModifier,
                      view_->pieceLabelPosition(torso));
    QCOMPARE(selection.count(), 1);
    QCOMPARE(selection.takeFirst().at(0).value<QList<int>>(), QList<int>({torso}));

    // One highlight per stitch (not dart) with the selected piece on either side.
    auto stitches_of = [&](QList<int> pieces) {
      int count = 0;
      for (const StitchPairs& pairs : garment_->stitches) {
        const Stitch& stitch = garment_->pattern.stitches[pairs.stitch];
        if (pieces.contains(stitch.a.panel) || pieces.contains(stitch.b.panel)) ++count;
      }
      return count;
    };
    QVERIFY(stitches_of({torso}) > 0);
    QCOMPARE(view_->sewingHighlightCount(), stitches_of({torso}));

    const int sleeve = garment_->pattern.panel_index("left_sleeve_f");
    QTest::mouseClick(view_->viewport(), Qt::LeftButton, Qt::ControlModifier,
                      view_->pieceLabelPosition(sleeve));
    QCOMPARE(view_->selectedPieces(), QList<int>({torso, sleeve}));
    QCOMPARE(view_->sewingHighlightCount(), stitches_of({torso, sleeve}));

    // Ctrl+click on a selected piece removes it; a plain click elsewhere replaces the selection.
    QTest::mouseClick(view_->viewport(), Qt::LeftButton, Qt::ControlModifier,
                      view_->pieceLabelPosition(torso));
    QCOMPARE(view_->selectedPieces(), QList<int>({sleeve}));
    QTest::mouseClick(view_->viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(2, 2));
    QCOMPARE(view_->pieceAt(QPoint(2, 2)), -1);
    QCOMPARE(view_->selectedPieces(), QList<int>());
    QCOMPARE(view_->sewingHighlightCount(), 0);

    // Mirroring a selection from elsewhere does not echo it back.
    selection.clear();
    view_->setSelectedPieces({0, 1, 99});
    QCOMPARE(view_->selectedPieces(), QList<int>({0, 1}));
    QCOMPARE(selection.count(), 0);
  }

  void wheelZoomsAndFrameAllRestores() {
    const double framed = view_->transform().m11();
    QWheelEvent wheel(QPointF(320, 240), view_->viewport()->mapToGlobal(QPointF(320, 240)),
                      QPoint(), QPoint(0, 480), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                      false);
    QApplication::sendEvent(view_->viewport(), &wheel);
    QVERIFY(view_->transform().m11() > 1.5 * framed);
    view_->frameAll();
    QVERIFY(std::abs(view_->transform().m11() - framed) < 1e-6 * framed);
  }

  void clearingTheGarmentEmptiesTheView() {
    view_->setGarment(nullptr);
    QVERIFY(view_->scene()->items().isEmpty());
    QCOMPARE(view_->pieceAt(QPoint(320, 240)), -1);
  }
};

GARMENT_UI_TEST_MAIN(PatternViewTest)
#include "test_pattern_view.moc"
