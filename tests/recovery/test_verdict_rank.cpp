// The order of verdicts the recovery keeps its best attempt by (engine/recovery/verdict_rank.h):
// clean first, then fewer failure kinds, then a smaller total excess; the excess of each kind
// as judge_garment reports it (counts, strain points, gap millimetres).

#include <QtTest>

#include "engine/quality/verdict.h"
#include "engine/recovery/verdict_rank.h"

using namespace garment;

namespace {

QualityFailure failure(FailureKind kind, double excess) {
  QualityFailure made;
  made.kind = kind;
  made.excess = excess;
  return made;
}

QualityVerdict verdict(std::vector<QualityFailure> failures) {
  QualityVerdict made;
  made.failures = std::move(failures);
  return made;
}

Garment two_pieces() {
  Garment garment;
  garment.pieces.resize(2);
  garment.pieces[0].name = "front";
  garment.pieces[1].name = "back";
  return garment;
}

}  // namespace

class VerdictRankTest : public QObject {
  Q_OBJECT
 private slots:
  void cleanBeatsAnyFailure() {
    const VerdictRank clean = rank_verdict(verdict({}));
    const VerdictRank one = rank_verdict(verdict({failure(FailureKind::SeamGap, 0.1)}));
    QCOMPARE(clean.kinds, 0);
    QCOMPARE(clean.excess, 0.0);
    QVERIFY(better_rank(clean, one));
    QVERIFY(!better_rank(one, clean));
  }

  void fewerKindsBeatSmallerExcess() {
    // One kind far past its threshold is still better than two kinds narrowly past theirs.
    const VerdictRank one = rank_verdict(verdict({failure(FailureKind::SelfCrossing, 500)}));
    const VerdictRank two = rank_verdict(
        verdict({failure(FailureKind::Strain, 0.5), failure(FailureKind::SeamGap, 0.2)}));
    QCOMPARE(two.kinds, 2);
    QCOMPARE(two.excess, 0.7);
    QVERIFY(better_rank(one, two));
    QVERIFY(!better_rank(two, one));
  }

  void sameKindsCompareByExcess() {
    const VerdictRank narrow = rank_verdict(verdict({failure(FailureKind::Fold, 2)}));
    const VerdictRank wide = rank_verdict(verdict({failure(FailureKind::Fold, 9)}));
    QVERIFY(better_rank(narrow, wide));
    QVERIFY(!better_rank(wide, narrow));
    // Equal ranks: neither is better, so the earlier attempt stays.
    QVERIFY(!better_rank(narrow, narrow));
  }

  void judgeGarmentStatesTheExcessInItsUnits() {
    const Garment garment = two_pieces();
    GarmentMetrics metrics;
    metrics.piece_inside_vertices = {3, 0};
    metrics.piece_crossing_edges = {0, 2};
    metrics.piece_folds = {0, 0};
    metrics.piece_max_strain = {0.26, 0.1};
    metrics.body_inside_vertices = 3;
    metrics.body_crossing_edges = 2;
    metrics.max_strain = 0.26;        // 6 points over 20 %
    metrics.max_seam_gap_m = 0.0075;  // 2.5 mm over 5 mm
    metrics.stitch_max_gap_m = {};
    const QualityVerdict judged = judge_garment(garment, metrics);
    QCOMPARE(judged.failures.size(), std::size_t(3));
    QCOMPARE(judged.failures[0].kind, FailureKind::BodyPenetration);
    QCOMPARE(judged.failures[0].excess, 5.0);
    QCOMPARE(judged.failures[1].kind, FailureKind::Strain);
    QVERIFY(std::abs(judged.failures[1].excess - 6.0) < 1e-9);
    QCOMPARE(judged.failures[2].kind, FailureKind::SeamGap);
    QVERIFY(std::abs(judged.failures[2].excess - 2.5) < 1e-9);
  }
};

QTEST_APPLESS_MAIN(VerdictRankTest)
#include "test_verdict_rank.moc"
