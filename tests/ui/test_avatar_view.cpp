// The 3D view renders what it is given: the body differs from the background, the garment shows
// its outside colour from the front and its inside colour from behind, a flipped piece stands out,
// markers are drawn and highlighted, picking finds the piece under the cursor, and only the latest
// snapshot of positions is kept.

#include <QSignalSpy>
#include <QtTest>

#include "tests/ui/ui_test_support.h"
#include "ui/avatar_view.h"

using namespace garment;
using garment::test::count_pixels;

class AvatarViewTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<ui::AvatarView> view_;
  std::shared_ptr<const Garment> garment_;

  QImage render() {
    view_->update();
    QCoreApplication::processEvents();
    return view_->grabFramebuffer();
  }

  // The demo's pieces laid out in a plane in front of a sphere body, seen from the front.
  void showFlatGarment() {
    test::show_flat_before_sphere(*view_, garment_, Eigen::Vector3d(0, 1, 0), 0.3, 0.5, 0.8);
  }

 private slots:
  // One view (one OpenGL context, shaders compiled once) for all tests; init() empties it.
  void initTestCase() {
    test::show_avatar_view(view_);
    if (QTest::currentTestFailed()) return;
    garment_ = test::demo_garment();
  }

  void init() {
    view_->setBody(nullptr);
    view_->setGarment(nullptr);
    view_->setBodyLocations({});
    view_->setOrbit(0, 8);
  }

  void cleanupTestCase() { view_.reset(); }

  void bodyDiffersFromBackground() {
    const QImage empty = render();
    const QColor background = view_->colours().background;
    QCOMPARE(count_pixels(empty, [&](QColor c) { return !test::colours_close(c, background, 2); }),
             0);

    view_->setBody(test::sphere_body(Eigen::Vector3d(0, 1, 0), 0.3));
    const QImage image = render();
    const int body_pixels =
        count_pixels(image, [&](QColor c) { return !test::colours_close(c, background, 10); });
    // The framed sphere covers a large disc in the middle of the view.
    GARMENT_VERIFY_IMAGE(body_pixels > image.width() * image.height() / 10, image, "avatar_body");
    const QColor centre = image.pixelColor(image.width() / 2, image.height() / 2);
    GARMENT_VERIFY_IMAGE(!test::colours_close(centre, background, 30), image, "avatar_body_centre");
  }

  void garmentHiddenUntilPositionsArrive() {
    view_->setBody(test::sphere_body(Eigen::Vector3d(0, 1, 0), 0.3));
    view_->setGarment(garment_);
    const QImage image = render();
    QVERIFY(!view_->garmentShown());
    GARMENT_VERIFY_IMAGE(count_pixels(image, test::looks_outside) == 0, image, "avatar_no_garment");
    // Positions that do not fit the garment are not drawn either.
    view_->setGarmentPositions(std::make_shared<Eigen::MatrixX3d>(Eigen::MatrixX3d::Zero(5, 3)));
    QVERIFY(!view_->garmentShown());
  }

  void outsideFromFrontInsideFromBehind() {
    showFlatGarment();
    const QImage front = render();
    const int front_outside = count_pixels(front, test::looks_outside);
    const int front_inside = count_pixels(front, test::looks_inside);
    GARMENT_VERIFY_IMAGE(front_outside > 2000 && front_inside == 0, front, "avatar_garment_front");

    view_->setOrbit(180, 0);
    const QImage back = render();
    const int back_outside = count_pixels(back, test::looks_outside);
    const int back_inside = count_pixels(back, test::looks_inside);
    GARMENT_VERIFY_IMAGE(back_inside > 2000 && back_outside == 0, back, "avatar_garment_back");
  }

  void flippedPieceShowsInsideColour() {
    // Mirroring one piece reverses its winding: seen from the front, it shows its inside.
    showFlatGarment();
    auto positions = test::sheet_positions(*garment_, 0.5, 1.0, 0.8);
    const int flipped = 0;
    const Piece& piece = garment_->pieces[flipped];
    auto rows = positions->middleRows(piece.first_vertex, piece.vertex_count);
    const double middle = 0.5 * (rows.col(0).minCoeff() + rows.col(0).maxCoeff());
    rows.col(0) = (2.0 * middle - rows.col(0).array()).matrix();
    view_->setGarmentPositions(positions);
    const QImage image = render();
    for (int p = 0; p < static_cast<int>(garment_->pieces.size()); ++p) {
      const QPoint at =
          view_->projectToView(test::point_inside_piece(*garment_, *positions, p)).toPoint();
      const QColor colour = image.pixelColor(at * image.devicePixelRatio());
      GARMENT_VERIFY_IMAGE(p == flipped ? test::looks_inside(colour) : test::looks_outside(colour),
                           image, QString("avatar_flipped_piece_%1").arg(p));
    }
  }

  void selectedPieceIsHighlighted() {
    showFlatGarment();
    auto positions = test::sheet_positions(*garment_, 0.5, 1.0, 0.8);
    const QPoint at =
        view_->projectToView(test::point_inside_piece(*garment_, *positions, 2)).toPoint();
    const QImage before = render();
    auto outline_pixels = [&](const QImage& image) {
      return test::count_pixels(
          image, [&](QColor c) { return test::colours_close(c, view_->colours().highlight, 12); });
    };
    QCOMPARE(outline_pixels(before), 0);
    view_->setSelectedPieces({2});
    const QImage image = render();
    // The piece is outlined in the highlight colour and its surface tinted towards it.
    GARMENT_VERIFY_IMAGE(outline_pixels(image) > 100, image, "avatar_selected_outline");
    const QColor tinted = image.pixelColor(at);
    GARMENT_VERIFY_IMAGE(
        tinted.red() > before.pixelColor(at).red() + 25 &&
            test::looks_outside(tinted) == test::looks_outside(before.pixelColor(at)),
        image, "avatar_selected_tint");
    // Outlines are drawn over the body: a piece behind it still shows its outline.
    view_->setOrbit(180, 0);
    const QImage behind = render();
    GARMENT_VERIFY_IMAGE(outline_pixels(behind) > 30, behind, "avatar_selected_outline_behind");
  }

  void pickingFindsTheVisiblePiece() {
    showFlatGarment();
    auto positions = test::sheet_positions(*garment_, 0.5, 1.0, 0.8);
    render();
    QSignalSpy selection(view_.get(), &ui::AvatarView::pieceSelectionChanged);
    for (int p = 0; p < static_cast<int>(garment_->pieces.size()); ++p) {
      const QPoint at =
          view_->projectToView(test::point_inside_piece(*garment_, *positions, p)).toPoint();
      QCOMPARE(view_->pieceAt(at), p);
    }
    const QPoint piece3 =
        view_->projectToView(test::point_inside_piece(*garment_, *positions, 3)).toPoint();
    QTest::mouseClick(view_.get(), Qt::LeftButton, Qt::NoModifier, piece3);
    QCOMPARE(selection.count(), 1);
    QCOMPARE(selection.takeFirst().at(0).value<QList<int>>(), QList<int>({3}));
    QCOMPARE(view_->selectedPieces(), QList<int>({3}));

    const QPoint piece5 =
        view_->projectToView(test::point_inside_piece(*garment_, *positions, 5)).toPoint();
    QTest::mouseClick(view_.get(), Qt::LeftButton, Qt::ControlModifier, piece5);
    QCOMPARE(view_->selectedPieces(), QList<int>({3, 5}));

    // A click on the background clears the selection; the body is never a piece.
    QCOMPARE(view_->pieceAt(QPoint(2, 2)), -1);
    QTest::mouseClick(view_.get(), Qt::LeftButton, Qt::NoModifier, QPoint(2, 2));
    QCOMPARE(view_->selectedPieces(), QList<int>());

    // Hidden pieces are not drawn, so not picked.
    std::vector<bool> visible(garment_->pieces.size(), true);
    visible[3] = false;
    view_->setPieceVisibility(visible);
    QCOMPARE(view_->pieceAt(piece3), -1);
  }

  void dragOrbitsWithoutSelecting() {
    showFlatGarment();
    auto positions = test::sheet_positions(*garment_, 0.5, 1.0, 0.8);
    const QImage before = render();
    const QPoint start =
        view_->projectToView(test::point_inside_piece(*garment_, *positions, 1)).toPoint();
    QSignalSpy selection(view_.get(), &ui::AvatarView::pieceSelectionChanged);
    QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, start);
    QMouseEvent move(QEvent::MouseMove, QPointF(start + QPoint(150, 0)),
                     view_->mapToGlobal(QPointF(start + QPoint(150, 0))), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view_.get(), &move);
    QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, start + QPoint(150, 0));
    QCOMPARE(selection.count(), 0);
    const QImage after = render();
    QVERIFY(after != before);
    // Orbiting 60° shows the garment plane obliquely: fewer garment pixels.
    GARMENT_VERIFY_IMAGE(
        count_pixels(after, test::looks_outside) < count_pixels(before, test::looks_outside), after,
        "avatar_orbit");
  }

  void markersAndHighlight() {
    view_->setBody(test::sphere_body(Eigen::Vector3d(0, 1, 0), 0.3));
    view_->setOrbit(0, 0);
    std::vector<ui::BodyLocationMarker> markers = {
        // Inside the sphere, 0.23 m behind its surface along the view ray: drawn as if on the
        // surface of a limb about that thick.
        {"neck", Eigen::Vector3d(0, 1.25, 0), Eigen::Vector3d::UnitY(), 0.22},
        {"chest_front", Eigen::Vector3d(0.1, 1.0, 0.3), Eigen::Vector3d::UnitZ()},
    };
    view_->setBodyLocations(markers);
    render();
    const QPoint chest = view_->projectToView(markers[1].centre).toPoint();
    const QPoint neck = view_->projectToView(markers[0].centre).toPoint();
    QImage image = render();
    GARMENT_VERIFY_IMAGE(test::colours_close(image.pixelColor(chest), view_->colours().marker, 12),
                         image, "avatar_marker");
    view_->setHighlightedLocation(1);
    image = render();
    GARMENT_VERIFY_IMAGE(
        test::colours_close(image.pixelColor(chest), view_->colours().highlighted_marker, 12) &&
            test::colours_close(image.pixelColor(neck), view_->colours().marker, 12),
        image, "avatar_marker_highlighted");
    QCOMPARE(view_->highlightedLocation(), 1);
    view_->setHighlightedLocation(7);  // out of range: none
    QCOMPARE(view_->highlightedLocation(), -1);
  }

  void onlyTheLatestSnapshotIsKept() {
    showFlatGarment();
    auto first = test::sheet_positions(*garment_, 0.5, 1.0, 0.8);
    auto second = test::sheet_positions(*garment_, 0.5, 1.0, 0.8);
    first->col(0).array() -= 5.0;  // far out of view
    std::weak_ptr<Eigen::MatrixX3d> first_alive = first;
    view_->setGarmentPositions(std::move(first));
    view_->setGarmentPositions(second);
    // The view let go of the first snapshot before it was ever drawn.
    QVERIFY(first_alive.expired());
    const QImage image = render();
    const QPoint at =
        view_->projectToView(test::point_inside_piece(*garment_, *second, 0)).toPoint();
    GARMENT_VERIFY_IMAGE(test::looks_outside(image.pixelColor(at)), image,
                         "avatar_latest_snapshot");
  }
};

GARMENT_UI_TEST_MAIN(AvatarViewTest)
#include "test_avatar_view.moc"
