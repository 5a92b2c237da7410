// The 3D view's diagnostics, display and camera (issue 42 items 2 and 3), on real patterns (the
// bundled demo and tests/data's four-panel skirt) in front of or through a sphere body:
// - overlays: the strain map turns a stretched piece red, vertices inside the body are flagged and
//   drawn, seams are drawn coloured by their gap, folds are marked, the batch in progress is
//   outlined and waiting pieces faded; the legend lists what is on; diagnostics that do not fit
//   the garment are ignored;
// - display: wireframe, the body shown / see-through / hidden, markers hidden behind the body and
//   on request;
// - camera: the view keys turn the camera (front and back 180° apart), the wheel zooms towards the
//   point under the cursor, right drag pans, Frame selected enlarges the selection inside the view;
// - the pattern view's legend shows the colours of the piece states.

#include <QAction>
#include <QMenu>
#include <QSignalSpy>
#include <QtTest>

#include "support/test_paths.h"
#include "tests/ui/ui_test_support.h"
#include "ui/avatar_view.h"
#include "ui/colour_legend.h"
#include "ui/garment_diagnostics_worker.h"
#include "ui/main_window.h"
#include "ui/pattern_view.h"

using namespace garment;
using garment::test::count_pixels;

namespace {

const Eigen::Vector3d kSphereCentre(0, 1, 0);
constexpr double kSphereRadius = 0.3;

bool reddish(const QColor& c) {
  return c.red() > c.green() + 60 && c.red() > c.blue() + 60;
}
bool greenish(const QColor& c) {
  return c.green() > c.red() + 40 && c.green() > c.blue() + 40;
}
bool bluish(const QColor& c) {
  return c.blue() > c.red() + 40 && c.blue() > c.green();
}

// Sum of absolute channel differences.
int colour_distance(const QColor& a, const QColor& b) {
  return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) +
         std::abs(a.blue() - b.blue());
}

// The rectangle of the projections of a piece's vertices.
QRectF projected_piece_box(const ui::AvatarView& view, const Garment& garment,
                           const Eigen::MatrixX3d& positions, int piece) {
  const Piece& p = garment.pieces[piece];
  QPointF lower(1e9, 1e9), upper(-1e9, -1e9);
  for (int v = p.first_vertex; v < p.first_vertex + p.vertex_count; ++v) {
    const QPointF at = view.projectToView(positions.row(v).transpose());
    lower = QPointF(std::min(lower.x(), at.x()), std::min(lower.y(), at.y()));
    upper = QPointF(std::max(upper.x(), at.x()), std::max(upper.y(), at.y()));
  }
  return QRectF(lower, upper);
}

}  // namespace

class AvatarOverlaysTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<ui::AvatarView> view_;
  std::shared_ptr<const Garment> demo_, skirt_;

  QImage render() {
    view_->update();
    QCoreApplication::processEvents();
    return view_->grabFramebuffer();
  }

  QColor pixelAt(const QImage& image, const Eigen::Vector3d& point) {
    return image.pixelColor(view_->projectToView(point).toPoint() * image.devicePixelRatio());
  }

  // Shows positions and waits for the worker's diagnostics of them (an overlay that needs them
  // must be on).
  bool showAndMeasure(std::shared_ptr<const Eigen::MatrixX3d> positions) {
    QSignalSpy ready(view_->diagnosticsWorker(), &ui::GarmentDiagnosticsWorker::diagnosticsReady);
    view_->setGarmentPositions(positions);
    // A measurement of earlier positions may be running: wait for the one of these.
    while (ready.wait(60000)) {
      if (!view_->diagnosticsWorker()->busy()) return view_->diagnostics() != nullptr;
    }
    return false;
  }

  void showFlat(std::shared_ptr<const Garment> garment, double depth, double scale) {
    test::show_flat_before_sphere(*view_, std::move(garment), kSphereCentre, kSphereRadius, depth,
                                  scale);
  }

 private slots:
  void initTestCase() {
    test::show_avatar_view(view_);
    if (QTest::currentTestFailed()) return;
    demo_ = test::demo_garment();
    skirt_ = std::make_shared<const Garment>(build_garment(load_pattern(
        test::test_data(std::filesystem::path("patterns") / "skirts__skirt_4_panels.json")
            .string())));
  }

  void init() {
    view_->setGarment(nullptr);
    view_->setBody(nullptr);
    for (int o = 0; o < ui::AvatarView::kOverlayCount; ++o)
      view_->setOverlay(static_cast<ui::AvatarView::Overlay>(o), false);
    view_->setWireframe(false);
    view_->setBodyDisplay(ui::AvatarView::BodyDisplay::Shown);
    view_->setMarkersShown(true);
    view_->setBodyLocations({});
    view_->setOrbit(0, 8);
  }

  void cleanupTestCase() { view_.reset(); }

  void strainMapColoursTheStretchedPiece() {
    // At the pattern's own scale: every edge at its rest length.
    showFlat(demo_, 0.5, 1.0);
    auto positions = test::sheet_positions(*demo_, 0.5, 1.0, 1.0);
    // Piece 0 stretched by 30 % across, about its middle, and brought 1 cm forward so that it
    // stays in front of the neighbours it now overlaps.
    const int stretched = 0, plain = 1;
    const Piece& piece = demo_->pieces[stretched];
    auto rows = positions->middleRows(piece.first_vertex, piece.vertex_count);
    const double middle = 0.5 * (rows.col(0).minCoeff() + rows.col(0).maxCoeff());
    rows.col(0) = ((rows.col(0).array() - middle) * 1.3 + middle).matrix();
    rows.col(2).array() += 0.01;
    view_->setGarmentPositions(positions);
    const Eigen::Vector3d in_stretched = test::point_inside_piece(*demo_, *positions, stretched);
    const Eigen::Vector3d in_plain = test::point_inside_piece(*demo_, *positions, plain);
    const QImage off = render();
    GARMENT_VERIFY_IMAGE(test::looks_outside(pixelAt(off, in_stretched)), off, "strain_off");

    view_->setOverlay(ui::AvatarView::Overlay::Strain, true);
    QVERIFY(showAndMeasure(positions));
    // The checker measured up to 30 % on the stretched piece (on its edges across) and nothing on
    // the other.
    const Eigen::VectorXd& strain = view_->diagnostics()->vertex_strain;
    const double most = strain.segment(piece.first_vertex, piece.vertex_count).maxCoeff();
    QVERIFY2(most > 0.25 && most < 0.3 + 1e-9, qPrintable(QString::number(most)));
    const Piece& other = demo_->pieces[plain];
    QVERIFY(strain.segment(other.first_vertex, other.vertex_count).maxCoeff() < 1e-9);
    const QImage on = render();
    GARMENT_VERIFY_IMAGE(reddish(pixelAt(on, in_stretched)), on, "strain_on_stretched");
    GARMENT_VERIFY_IMAGE(bluish(pixelAt(on, in_plain)), on, "strain_on_plain");
    QCOMPARE(view_->legend()->entries().size(), 4);
    QCOMPARE(view_->legend()->entries().back().colour,
             ui::AvatarView::strainColour(ui::AvatarView::kStrainFullScale));

    view_->setOverlay(ui::AvatarView::Overlay::Strain, false);
    const QImage again = render();
    GARMENT_VERIFY_IMAGE(test::looks_outside(pixelAt(again, in_stretched)), again, "strain_again");
    QVERIFY(view_->legend()->isHidden());
  }

  void verticesInsideTheBodyAreFlagged() {
    // The skirt's panels laid out in the plane through the sphere's centre, wider than the sphere.
    view_->setOverlay(ui::AvatarView::Overlay::Penetration, true);
    showFlat(skirt_, 0.0, 0.5);
    auto positions = test::sheet_positions(*skirt_, 0.0, 1.0, 0.5);
    QVERIFY(showAndMeasure(positions));
    const GarmentDiagnostics& d = *view_->diagnostics();
    QCOMPARE(d.vertex_inside_body.size(), std::size_t(skirt_->vertex_count()));
    // The sphere's polygons lie between its inradius (cos(π/24) of the radius) and its radius.
    const double inradius = kSphereRadius * std::cos(M_PI / 24.0);
    int surely_inside = 0, deepest = -1;
    for (int v = 0; v < skirt_->vertex_count(); ++v) {
      const double distance = (positions->row(v).transpose() - kSphereCentre).norm();
      if (distance < inradius - 1e-3) {
        QVERIFY2(d.vertex_inside_body[v], qPrintable(QString("vertex %1 not flagged").arg(v)));
        ++surely_inside;
        if (deepest < 0 || distance < (positions->row(deepest).transpose() - kSphereCentre).norm())
          deepest = v;
      }
      if (distance > kSphereRadius + 1e-3) QVERIFY(!d.vertex_inside_body[v]);
    }
    QVERIFY(surely_inside > 20);
    QVERIFY(d.body_crossing_edges.rows() > 0);
    // Drawn over the body in the penetration colour.
    const QImage image = render();
    const QColor flagged = pixelAt(image, positions->row(deepest).transpose());
    GARMENT_VERIFY_IMAGE(test::colours_close(flagged, view_->colours().inside_body, 12), image,
                         "penetration_inside_vertex");
    QCOMPARE(view_->legend()->entries().size(), 2);
  }

  void seamsDrawnColouredByGap() {
    view_->setOverlay(ui::AvatarView::Overlay::Seams, true);
    showFlat(demo_, 0.5, 0.8);
    auto positions = test::sheet_positions(*demo_, 0.5, 1.0, 0.8);
    // One sewing pair closed: its second vertex moved onto its first. The pair is chosen among
    // those whose vertices belong to no other pair, far from the others on screen.
    const Eigen::MatrixX2i& pairs = demo_->sewing_pairs;
    std::map<int, int> uses;
    for (Eigen::Index k = 0; k < pairs.rows(); ++k)
      for (int side = 0; side < 2; ++side)
        ++uses[pairs(k, side)];
    Eigen::Index closed = -1;
    for (Eigen::Index k = pairs.rows() / 2; k < pairs.rows() && closed < 0; ++k)
      if (uses[pairs(k, 0)] == 1 && uses[pairs(k, 1)] == 1) closed = k;
    QVERIFY(closed >= 0);
    positions->row(pairs(closed, 1)) = positions->row(pairs(closed, 0));
    QVERIFY(showAndMeasure(positions));
    const GarmentDiagnostics& d = *view_->diagnostics();
    QCOMPARE(d.sewing_pair_gap_m.size(), pairs.rows());
    for (Eigen::Index k = 0; k < pairs.rows(); ++k)
      QVERIFY(std::abs(d.sewing_pair_gap_m(k) -
                       (positions->row(pairs(k, 0)) - positions->row(pairs(k, 1))).norm()) < 1e-12);
    QCOMPARE(d.sewing_pair_gap_m(closed), 0.0);

    const QImage image = render();
    const QColor closed_colour = pixelAt(image, positions->row(pairs(closed, 0)).transpose());
    GARMENT_VERIFY_IMAGE(greenish(closed_colour), image, "seam_closed");
    // A pair laid out more than 5 cm apart: its ends are drawn in the open colour.
    Eigen::Index open = -1;
    for (Eigen::Index k = 0; k < pairs.rows() && open < 0; ++k)
      if (d.sewing_pair_gap_m(k) > 0.1 && uses[pairs(k, 0)] == 1 && uses[pairs(k, 1)] == 1)
        open = k;
    QVERIFY(open >= 0);
    const QColor open_colour = pixelAt(image, positions->row(pairs(open, 1)).transpose());
    GARMENT_VERIFY_IMAGE(test::colours_close(open_colour, view_->colours().seam_open, 12), image,
                         "seam_open");
    QCOMPARE(view_->legend()->entries().size(), 3);
  }

  void foldsMarked() {
    view_->setOverlay(ui::AvatarView::Overlay::Folds, true);
    showFlat(demo_, 0.5, 0.8);
    auto positions = test::sheet_positions(*demo_, 0.5, 1.0, 0.8);
    QVERIFY(showAndMeasure(positions));
    QCOMPARE(view_->diagnostics()->fold_edges.rows(), Eigen::Index(0));
    // Piece 2's right half turned 160° about the vertical line through its middle, towards the
    // camera: the triangles either side of that line face nearly opposite ways.
    const int folded = 2;
    const Piece& piece = demo_->pieces[folded];
    auto rows = positions->middleRows(piece.first_vertex, piece.vertex_count);
    const double middle = 0.5 * (rows.col(0).minCoeff() + rows.col(0).maxCoeff());
    const double angle = 160.0 * M_PI / 180.0;
    for (Eigen::Index v = 0; v < rows.rows(); ++v) {
      const double along = rows(v, 0) - middle;
      if (along <= 0.0) continue;
      rows(v, 0) = middle + along * std::cos(angle);
      rows(v, 2) = 0.5 + along * std::sin(angle);
    }
    QVERIFY(showAndMeasure(positions));
    const GarmentDiagnostics& d = *view_->diagnostics();
    QVERIFY(d.fold_edges.rows() > 0);
    double longest_edge = 0.0;
    for (int t = piece.first_triangle; t < piece.first_triangle + piece.triangle_count; ++t)
      for (int k = 0; k < 3; ++k)
        longest_edge =
            std::max(longest_edge, (demo_->rest_positions.row(demo_->triangles(t, k)) -
                                    demo_->rest_positions.row(demo_->triangles(t, (k + 1) % 3)))
                                       .norm());
    for (Eigen::Index f = 0; f < d.fold_edges.rows(); ++f) {
      QCOMPARE(demo_->vertex_piece(d.fold_edges(f, 0)), folded);
      // On the crease, within an edge of the pattern's mesh (scaled by the sheet's 0.8).
      QVERIFY(std::abs((*positions)(d.fold_edges(f, 0), 0) - middle) < 0.8 * longest_edge + 1e-9);
    }
    const QImage image = render();
    const QColor marked = pixelAt(image, positions->row(d.fold_edges(0, 0)).transpose());
    GARMENT_VERIFY_IMAGE(test::colours_close(marked, view_->colours().fold, 12), image, "fold");
    QCOMPARE(view_->legend()->entries().size(), 1);
  }

  void batchInProgressSetApart() {
    showFlat(demo_, 0.5, 0.8);
    auto positions = test::sheet_positions(*demo_, 0.5, 1.0, 0.8);
    const int in_batch = 1, waiting = 2;
    std::vector<ui::PieceState> states(demo_->pieces.size(), ui::PieceState::Arranged);
    states[in_batch] = ui::PieceState::InBatch;
    states[waiting] = ui::PieceState::Waiting;
    view_->setPieceStates(states);
    const QColor batch_colour = ui::piece_state_colour(ui::PieceState::InBatch);
    const auto batch_outline = [&](const QImage& image) {
      return count_pixels(image,
                          [&](QColor c) { return test::colours_close(c, batch_colour, 12); });
    };
    const Eigen::Vector3d in_waiting = test::point_inside_piece(*demo_, *positions, waiting);
    const QColor background = view_->colours().background;
    const QImage off = render();  // the overlay is off (init)
    QCOMPARE(batch_outline(off), 0);
    view_->setOverlay(ui::AvatarView::Overlay::Batch, true);
    const QImage on = render();
    GARMENT_VERIFY_IMAGE(batch_outline(on) > 100, on, "batch_outline");
    // The waiting piece is faded towards the background, at least halfway.
    const int before = colour_distance(pixelAt(off, in_waiting), background);
    const int after = colour_distance(pixelAt(on, in_waiting), background);
    GARMENT_VERIFY_IMAGE(after < before / 2, on, "batch_waiting_faded");
    // Arranged pieces keep their colours.
    const Eigen::Vector3d in_arranged = test::point_inside_piece(*demo_, *positions, 0);
    QVERIFY(test::colours_close(pixelAt(on, in_arranged), pixelAt(off, in_arranged), 3));
    QCOMPARE(view_->legend()->entries().size(), 2);
  }

  void legendListsWhatIsOnAndIsDrawn() {
    showFlat(demo_, 0.5, 0.8);
    QVERIFY(view_->legend()->isHidden());
    view_->setOverlay(ui::AvatarView::Overlay::Penetration, true);
    view_->setOverlay(ui::AvatarView::Overlay::Folds, true);
    const QList<ui::LegendEntry> entries = view_->legend()->entries();
    QCOMPARE(entries.size(), 3);
    QCOMPARE(entries[0].colour, view_->colours().inside_body);
    QCOMPARE(entries[1].colour, view_->colours().cloth_crossing);
    QCOMPARE(entries[2].colour, view_->colours().fold);
    QVERIFY(view_->legend()->isVisible());
    QVERIFY(view_->rect().contains(view_->legend()->geometry()));
    // Its swatches are on screen over the 3D view.
    render();
    const QImage shown = view_->grab().toImage();
    for (int k = 0; k < 3; ++k) {
      const QPoint at =
          view_->legend()->geometry().topLeft() + view_->legend()->swatchRect(k).center();
      GARMENT_VERIFY_IMAGE(test::colours_close(shown.pixelColor(at * shown.devicePixelRatio()),
                                               entries[k].colour, 8),
                           shown, QString("legend_swatch_%1").arg(k));
    }
  }

  void diagnosticsThatDoNotFitAreIgnored() {
    view_->setOverlay(ui::AvatarView::Overlay::Strain, true);
    view_->setOverlay(ui::AvatarView::Overlay::Penetration, true);
    showFlat(demo_, 0.5, 0.8);
    auto positions = test::sheet_positions(*demo_, 0.5, 1.0, 0.8);
    QVERIFY(showAndMeasure(positions));
    const QImage good = render();
    auto bad = std::make_shared<GarmentDiagnostics>(*view_->diagnostics());
    bad->vertex_strain = Eigen::VectorXd::Constant(demo_->vertex_count(), 1.0);
    bad->body_crossing_edges.resize(1, 2);
    bad->body_crossing_edges << 0, demo_->vertex_count() + 5;  // out of range
    view_->setDiagnostics(bad);
    const QImage image = render();
    // Not drawn: no red strain anywhere, though every strain is 100 %.
    GARMENT_VERIFY_IMAGE(count_pixels(image, reddish) == count_pixels(good, reddish), image,
                         "bad_diagnostics");
    view_->setDiagnostics(std::make_shared<GarmentDiagnostics>());
    render();
    // Positions that are not finite: the worker reports nothing instead of crashing.
    auto nan_positions = std::make_shared<Eigen::MatrixX3d>(*positions);
    (*nan_positions)(0, 0) = std::numeric_limits<double>::quiet_NaN();
    QSignalSpy ready(view_->diagnosticsWorker(), &ui::GarmentDiagnosticsWorker::diagnosticsReady);
    view_->setGarmentPositions(nan_positions);
    QVERIFY(ready.wait(60000));
    QVERIFY(!ready.last().at(0).value<std::shared_ptr<const GarmentDiagnostics>>());
  }

  void wireframeDrawsTheEdges() {
    showFlat(demo_, 0.5, 0.8);
    const QColor wire = view_->colours().wire;
    const auto wire_pixels = [&](const QImage& image) {
      return count_pixels(image, [&](QColor c) { return test::colours_close(c, wire, 6); });
    };
    const QImage plain = render();
    view_->setWireframe(true);
    const QImage wired = render();
    GARMENT_VERIFY_IMAGE(wire_pixels(wired) > wire_pixels(plain) + 1000, wired, "wireframe");
    GARMENT_VERIFY_IMAGE(
        count_pixels(wired, test::looks_outside) < count_pixels(plain, test::looks_outside), wired,
        "wireframe_surface");
  }

  void bodyShownSeeThroughHidden() {
    // The garment 0.5 m behind the sphere, seen from the front: the centroid of the garment's
    // triangle nearest to the sphere's axis is well inside the sphere's outline.
    showFlat(demo_, -0.5, 0.8);
    auto positions = test::sheet_positions(*demo_, -0.5, 1.0, 0.8);
    Eigen::Vector3d at = Eigen::Vector3d::Constant(1e9);
    int behind = -1;
    for (int t = 0; t < demo_->triangle_count(); ++t) {
      const Eigen::Vector3d centroid =
          (positions->row(demo_->triangles(t, 0)) + positions->row(demo_->triangles(t, 1)) +
           positions->row(demo_->triangles(t, 2)))
              .transpose() /
          3.0;
      if (std::hypot(centroid.x() - kSphereCentre.x(), centroid.y() - kSphereCentre.y()) <
          std::hypot(at.x() - kSphereCentre.x(), at.y() - kSphereCentre.y())) {
        at = centroid;
        behind = demo_->triangle_piece(t);
      }
    }
    QVERIFY(std::hypot(at.x() - kSphereCentre.x(), at.y() - kSphereCentre.y()) < 0.15);
    const QPoint pixel = view_->projectToView(at).toPoint();
    const QImage shown = render();
    const QColor body_colour = pixelAt(shown, at);
    GARMENT_VERIFY_IMAGE(!test::looks_outside(body_colour), shown, "body_shown");
    QCOMPARE(view_->pieceAt(pixel), -1);  // the body is in the way

    view_->setBodyDisplay(ui::AvatarView::BodyDisplay::SeeThrough);
    const QImage through = render();
    const QColor blended = pixelAt(through, at);
    GARMENT_VERIFY_IMAGE(
        test::looks_outside(blended) && !test::colours_close(blended, body_colour, 20), through,
        "body_see_through");
    QCOMPARE(view_->pieceAt(pixel), behind);  // picked through the body

    view_->setBodyDisplay(ui::AvatarView::BodyDisplay::Hidden);
    const QImage hidden = render();
    const QColor bare = pixelAt(hidden, at);
    GARMENT_VERIFY_IMAGE(test::looks_outside(bare) && colour_distance(bare, blended) > 20, hidden,
                         "body_hidden");
    QCOMPARE(view_->pieceAt(pixel), behind);
  }

  void markersHiddenBehindTheBodyAndOnRequest() {
    view_->setBody(test::sphere_body(kSphereCentre, kSphereRadius));
    view_->setOrbit(0, 0);
    // One marker in front of the sphere, one behind it, both plane markers (no limb radius).
    const std::vector<ui::BodyLocationMarker> markers = {
        {"chest_front", Eigen::Vector3d(0.1, 1.0, 0.32), Eigen::Vector3d::UnitZ()},
        {"chest_back", Eigen::Vector3d(-0.1, 1.05, -0.32), -Eigen::Vector3d::UnitZ()},
    };
    view_->setBodyLocations(markers);
    const QColor marker = view_->colours().marker;
    QImage image = render();
    GARMENT_VERIFY_IMAGE(test::colours_close(pixelAt(image, markers[0].centre), marker, 12), image,
                         "marker_front");
    GARMENT_VERIFY_IMAGE(!test::colours_close(pixelAt(image, markers[1].centre), marker, 40), image,
                         "marker_behind_hidden");
    // Seen through the body, the one behind shows.
    view_->setBodyDisplay(ui::AvatarView::BodyDisplay::SeeThrough);
    image = render();
    GARMENT_VERIFY_IMAGE(test::colours_close(pixelAt(image, markers[1].centre), marker, 12), image,
                         "marker_behind_see_through");
    view_->setMarkersShown(false);
    image = render();
    GARMENT_VERIFY_IMAGE(!test::colours_close(pixelAt(image, markers[0].centre), marker, 40) &&
                             !test::colours_close(pixelAt(image, markers[1].centre), marker, 40),
                         image, "markers_hidden");
  }

  void zoomTowardsTheCursorKeepsThePointUnderIt() {
    showFlat(demo_, 0.5, 0.8);
    auto positions = test::sheet_positions(*demo_, 0.5, 1.0, 0.8);
    render();
    // A point of a piece off the view's centre, and a second point to measure the zoom by.
    const Eigen::Vector3d anchor = test::point_inside_piece(*demo_, *positions, 0);
    const Eigen::Vector3d other = test::point_inside_piece(*demo_, *positions, 3);
    const QPointF cursor = view_->projectToView(anchor);
    QVERIFY((cursor - QPointF(view_->width() / 2.0, view_->height() / 2.0)).manhattanLength() > 40);
    const double spread_before = QLineF(cursor, view_->projectToView(other)).length();
    QWheelEvent wheel(cursor, view_->mapToGlobal(cursor), QPoint(), QPoint(0, 240), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view_.get(), &wheel);
    const QPointF after = view_->projectToView(anchor);
    QVERIFY2(QLineF(after, cursor).length() < 1.0,
             qPrintable(QString("moved %1 px").arg(QLineF(after, cursor).length())));
    // Zoomed in: the two points are further apart on screen (0.9985^-240 ≈ 1.43 times).
    const double spread_after = QLineF(after, view_->projectToView(other)).length();
    QVERIFY(spread_after > 1.3 * spread_before);
    // Over the background (no surface under the cursor) it zooms too, and never crashes.
    QWheelEvent out(QPointF(3, 3), view_->mapToGlobal(QPointF(3, 3)), QPoint(), QPoint(0, -240),
                    Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view_.get(), &out);
    QVERIFY(QLineF(view_->projectToView(anchor), view_->projectToView(other)).length() <
            spread_after);
  }

  void rightDragPans() {
    showFlat(demo_, 0.5, 0.8);
    auto positions = test::sheet_positions(*demo_, 0.5, 1.0, 0.8);
    render();
    const Eigen::Vector3d point = test::point_inside_piece(*demo_, *positions, 1);
    const QPointF before = view_->projectToView(point);
    const QPoint start(200, 200), end(260, 230);
    QTest::mousePress(view_.get(), Qt::RightButton, Qt::NoModifier, start);
    QMouseEvent move(QEvent::MouseMove, QPointF(end), view_->mapToGlobal(QPointF(end)),
                     Qt::NoButton, Qt::RightButton, Qt::NoModifier);
    QApplication::sendEvent(view_.get(), &move);
    QTest::mouseRelease(view_.get(), Qt::RightButton, Qt::NoModifier, end);
    const QPointF moved = view_->projectToView(point) - before;
    // The scene follows the cursor (by a pixel per pixel at the target's depth; the garment is a
    // little nearer) and the camera does not turn.
    QVERIFY2(moved.x() > 0.8 * 60 && moved.x() < 1.5 * 60 && moved.y() > 0.8 * 30 &&
                 moved.y() < 1.5 * 30,
             qPrintable(QString("moved by %1, %2").arg(moved.x()).arg(moved.y())));
    QCOMPARE(view_->orbitYaw(), 0.0);
    QCOMPARE(view_->orbitPitch(), 0.0);
  }

  void frameSelectedEnlargesTheSelection() {
    showFlat(demo_, 0.5, 0.8);
    auto positions = test::sheet_positions(*demo_, 0.5, 1.0, 0.8);
    // The smallest piece: framing it must enlarge it most.
    int smallest = 0;
    for (int p = 0; p < static_cast<int>(demo_->pieces.size()); ++p)
      if (demo_->pieces[p].vertex_count < demo_->pieces[smallest].vertex_count) smallest = p;
    view_->setSelectedPieces({smallest});
    const QRectF before = projected_piece_box(*view_, *demo_, *positions, smallest);
    view_->frameSelected();
    const QRectF after = projected_piece_box(*view_, *demo_, *positions, smallest);
    QVERIFY2(QRectF(view_->rect()).contains(after), qPrintable(QString("box %1,%2 %3x%4")
                                                                   .arg(after.x())
                                                                   .arg(after.y())
                                                                   .arg(after.width())
                                                                   .arg(after.height())));
    QVERIFY(after.width() * after.height() > 2.0 * before.width() * before.height());
    // And shown there.
    const QImage image = render();
    GARMENT_VERIFY_IMAGE(
        test::looks_outside(pixelAt(image, test::point_inside_piece(*demo_, *positions, smallest))),
        image, "frame_selected");
    // Nothing selected: the camera stays.
    view_->setSelectedPieces({});
    view_->frameSelected();
    QCOMPARE(projected_piece_box(*view_, *demo_, *positions, smallest), after);
  }

  void viewMenuKeysAndTooltips() {
    ui::MainWindow window;
    window.setErrorPresenter([](const QString&, const QString&) {});
    QVERIFY(window.openDemoPattern());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    ui::AvatarView* view = window.avatarView();
    view->setOrbit(33, 20);
    QTest::keyClick(&window, Qt::Key_1);
    QCOMPARE(view->orbitYaw(), 0.0);
    QCOMPARE(view->orbitPitch(), 0.0);
    QTest::keyClick(&window, Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(view->orbitYaw(), 180.0);
    QTest::keyClick(&window, Qt::Key_3);
    QCOMPARE(view->orbitYaw(), 270.0);
    QTest::keyClick(&window, Qt::Key_3, Qt::ControlModifier);
    QCOMPARE(view->orbitYaw(), 90.0);
    QTest::keyClick(&window, Qt::Key_F2);
    QVERIFY(view->overlay(ui::AvatarView::Overlay::Strain));
    QTest::keyClick(&window, Qt::Key_B, Qt::ShiftModifier);
    QCOMPARE(view->bodyDisplay(), ui::AvatarView::BodyDisplay::SeeThrough);
    QTest::keyClick(&window, Qt::Key_M);
    QVERIFY(!view->markersShown());
    QTest::keyClick(&window, Qt::Key_W);
    QVERIFY(view->wireframe());

    // Every entry is in the View menu and names its shortcut in its tooltip.
    const ui::AvatarViewActions& actions = window.avatarViewActions();
    QList<QAction*> all(std::begin(actions.overlays), std::end(actions.overlays));
    all << actions.wireframe << actions.body_shown << actions.body_see_through
        << actions.body_hidden << actions.markers << actions.view_front << actions.view_back
        << actions.view_right << actions.view_left << actions.frame_selected;
    QMenu* view_menu = nullptr;
    for (QMenu* menu : window.findChildren<QMenu*>())
      if (menu->title() == QObject::tr("&View")) view_menu = menu;
    QVERIFY(view_menu);
    QSet<QKeySequence> shortcuts;
    for (QAction* action : all) {
      QVERIFY(action && !action->shortcut().isEmpty());
      QVERIFY2(action->toolTip().contains(action->shortcut().toString(QKeySequence::NativeText)),
               qPrintable(action->toolTip()));
      QVERIFY(view_menu->findChildren<QAction*>().contains(action) ||
              std::any_of(view_menu->actions().begin(), view_menu->actions().end(),
                          [&](QAction* entry) {
                            return entry->menu() && entry->menu()->actions().contains(action);
                          }));
      shortcuts.insert(action->shortcut());
    }
    QCOMPARE(shortcuts.size(), all.size());  // no two share a key
    // Opening a pattern sends the piece states to both views: none waiting, no batch legend.
    QVERIFY(view->legend()->entries().size() == 4);  // the strain map's, turned on above
  }

  void patternLegendShowsThePieceStateColours() {
    ui::PatternView pattern;
    pattern.resize(500, 400);
    pattern.setGarment(demo_);
    pattern.show();
    QVERIFY(QTest::qWaitForWindowExposed(&pattern));
    const ui::ColourLegend* legend = pattern.legend();
    const std::vector<ui::PieceState> states = {ui::PieceState::Waiting, ui::PieceState::InBatch,
                                                ui::PieceState::Arranged, ui::PieceState::Seed};
    QCOMPARE(legend->entries().size(), qsizetype(states.size()));
    QVERIFY(legend->isVisible());
    QVERIFY(pattern.rect().contains(legend->geometry()));
    const QImage image = pattern.grab().toImage();
    for (std::size_t k = 0; k < states.size(); ++k) {
      QCOMPARE(legend->entries()[k].colour, ui::piece_state_colour(states[k]));
      QCOMPARE(legend->entries()[k].text, ui::piece_state_name(states[k]));
      const QPoint at = legend->geometry().topLeft() + legend->swatchRect(int(k)).center();
      GARMENT_VERIFY_IMAGE(test::colours_close(image.pixelColor(at * image.devicePixelRatio()),
                                               ui::piece_state_colour(states[k]), 6),
                           image, QString("pattern_legend_%1").arg(k));
    }
    // It stays in the corner when the view is resized.
    pattern.resize(700, 600);
    QCoreApplication::processEvents();
    QVERIFY(pattern.rect().contains(legend->geometry()));
    QVERIFY(legend->geometry().bottom() > 500);
  }
};

GARMENT_UI_TEST_MAIN(AvatarOverlaysTest)
#include "test_avatar_overlays.moc"
