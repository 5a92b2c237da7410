// Pieces turned inside out (engine/quality/piece_facing.h) on a real garment: gc_0007 (odd half,
// tests/data/patterns; a blouse with sleeves and cuffs) arranged on f_smpl_average_A40, which its
// first pass arranges clean.
// - arranged, no piece has more than a quarter of its area facing the body, and the verdict
//   passes;
// - the same positions with the left sleeve's front piece declared the other way round (its
//   triangles' winding reversed, as when its outside is the face towards the arm) give that
//   piece more than half of its area facing the body, and the verdict fails as misplaced, naming
//   it and "inside out", with no other failure;
// - collars and lapels fold over by design: a collar piece whose outside faces the body is not
//   called inside out, any other piece is; an entry already misplaced for another reason keeps
//   it and gains "inside out".

#include <QtTest>

#include "engine/quality/garment_metrics.h"
#include "engine/quality/piece_facing.h"
#include "engine/quality/verdict.h"
#include "engine/seeding/scene.h"
#include "engine/session/session.h"
#include "support/test_environment.h"
#include "support/test_paths.h"

using namespace garment;

class PieceFacingTest : public QObject {
  Q_OBJECT
 private slots:
  void anInsideOutSleeveFailsTheVerdict() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions are checked in the Release run");
    const std::shared_ptr<const Scene> scene =
        load_scene(test::test_data("patterns/gc_0007_specification.json"),
                   test::test_data("bodies/f_smpl_average_A40.obj"));
    Session session(scene);
    session.run();
    const BodyReference body(scene->body->mesh);
    const Garment& garment = *scene->garment;
    const std::vector<ExpectedRegion> regions = expected_regions_from_names(garment);
    const GarmentMetrics arranged = measure_garment(garment, session.positions(), &body, regions);
    QVERIFY2(judge_garment(garment, arranged).ok(), "gc_0007's first pass is expected clean");
    QCOMPARE(arranged.piece_area_facing_body.size(), garment.pieces.size());
    for (double share : arranged.piece_area_facing_body)
      QVERIFY(share >= 0.0 && share < 0.25);

    Garment turned = garment;
    const int sleeve = garment.pattern.panel_index("left_sleeve_f");
    QVERIFY(sleeve >= 0);
    for (int t = 0; t < turned.triangle_count(); ++t)
      if (turned.triangle_piece(t) == sleeve)
        std::swap(turned.triangles(t, 1), turned.triangles(t, 2));
    const GarmentMetrics metrics = measure_garment(turned, session.positions(), &body, regions);
    QVERIFY(metrics.piece_area_facing_body[sleeve] > 0.75);
    const QualityVerdict verdict = judge_garment(turned, metrics);
    QCOMPARE(verdict.failures.size(), std::size_t(1));
    QVERIFY(verdict.failed(FailureKind::Misplaced));
    QCOMPARE(verdict.failures[0].pieces, std::vector<int>{sleeve});
    QVERIFY2(verdict.failures[0].message.find("left_sleeve_f") != std::string::npos &&
                 verdict.failures[0].message.find("inside out") != std::string::npos,
             verdict.failures[0].message.c_str());
  }

  void collarsAndLapelsFoldOverByDesign() {
    QVERIFY(folds_over_by_design("left_collar_front"));
    QVERIFY(folds_over_by_design("collar"));
    QVERIFY(folds_over_by_design("lapel_right"));
    QVERIFY(!folds_over_by_design("left_sleeve_f"));
    QVERIFY(!folds_over_by_design("collarless_front"));
    QVERIFY(!folds_over_by_design(""));

    Garment garment;
    for (const char* name : {"left_collar_back", "skirt_front", "left_sleeve_b"}) {
      Piece piece;
      piece.name = name;
      garment.pieces.push_back(piece);
    }
    std::vector<Misplacement> misplaced{{2, "off the left arm"}};
    add_inside_out_pieces(garment, {0.9, 0.6, 0.7}, misplaced);
    QCOMPARE(misplaced.size(), std::size_t(2));
    QCOMPARE(misplaced[0].piece, 1);
    QCOMPARE(misplaced[0].problem, std::string("inside out"));
    QCOMPARE(misplaced[1].piece, 2);
    QCOMPARE(misplaced[1].problem, std::string("off the left arm, inside out"));

    std::vector<Misplacement> none;
    add_inside_out_pieces(garment, {0.9, 0.5, 0.1}, none);  // exactly one half is not past it
    QVERIFY(none.empty());
  }
};

QTEST_GUILESS_MAIN(PieceFacingTest)
#include "test_piece_facing.moc"
