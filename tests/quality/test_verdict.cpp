// The verdict (engine/quality/verdict.h) on seams and darts of a real pattern
// (tests/data/patterns/gc_0000_specification.json: a pencil skirt whose panels have darts):
// - with every sewing pair and dart pair joined (vertices of one welded class at one point) the
//   garment has no seam gap;
// - a dart's mouth opened by 8 mm (one dart pair apart, no stitch touched) fails the verdict as a
//   seam gap naming the dart's piece and "open dart mouths", while every stitch stays closed;
// - 4 mm open passes (the threshold is 5 mm).

#include <QtTest>

#include <set>

#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

// #V×3: the rest layout with each welded class (seams and darts joined) at its first vertex.
Eigen::MatrixX3d joined_positions(const Garment& garment) {
  const Eigen::VectorXi welded = weld_seams_and_darts(garment);
  const int count = garment.vertex_count();
  Eigen::MatrixX3d positions(count, 3);
  std::map<int, int> first_of_class;
  for (int v = 0; v < count; ++v) {
    const int first = first_of_class.emplace(welded(v), v).first->second;
    positions.row(v) << garment.rest_positions(first, 0), garment.rest_positions(first, 1), 0.0;
  }
  return positions;
}

// A dart pair whose two vertices are in no sewing pair, so that moving one opens the dart alone.
int lone_dart_pair(const Garment& garment) {
  std::set<int> sewn;
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    sewn.insert(garment.sewing_pairs(k, 0));
    sewn.insert(garment.sewing_pairs(k, 1));
  }
  for (Eigen::Index k = 0; k < garment.dart_pairs.rows(); ++k)
    if (!sewn.count(garment.dart_pairs(k, 0)) && !sewn.count(garment.dart_pairs(k, 1)))
      return static_cast<int>(k);
  return -1;
}

}  // namespace

class VerdictTest : public QObject {
  Q_OBJECT
 private slots:
  void anOpenDartMouthFailsTheVerdict() {
    const Garment garment =
        build_garment(load_pattern(test::test_data("patterns/gc_0000_specification.json")));
    QVERIFY(garment.dart_pairs.rows() > 0);
    Eigen::MatrixX3d positions = joined_positions(garment);
    const GarmentMetrics closed =
        measure_garment(garment, positions, nullptr, expected_regions_from_names(garment));
    QVERIFY(closed.max_seam_gap_m < 1e-12);
    QVERIFY(!judge_garment(garment, closed).failed(FailureKind::SeamGap));

    const int pair = lone_dart_pair(garment);
    QVERIFY(pair >= 0);
    const int moved = garment.dart_pairs(pair, 1);
    const int piece = garment.vertex_piece(moved);
    for (double opening : {0.004, 0.008}) {
      Eigen::MatrixX3d opened = positions;
      opened(moved, 2) += opening;
      const GarmentMetrics metrics =
          measure_garment(garment, opened, nullptr, expected_regions_from_names(garment));
      QVERIFY(std::abs(metrics.max_seam_gap_m - opening) < 1e-9);
      for (double gap : metrics.stitch_max_gap_m)
        QVERIFY(gap < 1e-12);  // every stitch closed: the gap is the dart's
      const QualityVerdict verdict = judge_garment(garment, metrics);
      if (opening < 0.005) {
        QVERIFY(!verdict.failed(FailureKind::SeamGap));
        continue;
      }
      QVERIFY(verdict.failed(FailureKind::SeamGap));
      // (The layout with welded classes joined has crossings and folds; only the gaps matter.)
      const QualityFailure& failure =
          *std::find_if(verdict.failures.begin(), verdict.failures.end(),
                        [](const QualityFailure& f) { return f.kind == FailureKind::SeamGap; });
      QCOMPARE(failure.pieces, (std::vector<int>{piece}));
      QVERIFY2(failure.message.find("0 open seams, 1 open dart mouths") != std::string::npos,
               failure.message.c_str());
      QVERIFY(failure.message.find(garment.pieces[piece].name) != std::string::npos);
    }
  }
};

QTEST_APPLESS_MAIN(VerdictTest)
#include "test_verdict.moc"
