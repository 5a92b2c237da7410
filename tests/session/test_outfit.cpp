// An outfit of two real garments on one body (issue "Complex garments"): tests/data/patterns'
// gc_0022 (a sleeveless top) and gc_0340 (a maxi pencil skirt with darts), both made for
// f_smpl_average_A40 and from the tuning half, on that body, both ways round: the top tucked in
// (top first, innermost) and worn over (skirt first); the two overlap by 13-15 cm. Each time:
// - the scene has the two garments, each with a seed of its own pieces;
// - every piece of the inner garment is arranged before any piece of the outer one, and the
//   outer garment's seed is recorded after the inner garment's batches;
// - the outfit is clean by the verdict, with no crossing between the garments;
// - the outer garment is outside the inner one: each outer vertex within 5 cm of the inner cloth
//   lies on the outside of its closest inner triangle (the triangle's +z, the pieces' outside).
//   The check has teeth: the same measure the other way round finds inner vertices inside the
//   outer garment, and there are enough vertices near each other for it to say something;
// - the recovery's reseed of the outer garment continues from the checkpoint before its seed,
//   where the inner garment is arranged and the outer one waits, with the seed asked for.

#include <QtTest>

#include <algorithm>

#include "engine/energy/triangle_closest_point.h"
#include "engine/quality/expected_region.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/outfit_crossings.h"
#include "engine/quality/verdict.h"
#include "engine/session/session.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

const std::filesystem::path kTop = "patterns/gc_0022_specification.json";
const std::filesystem::path kSkirt = "patterns/gc_0340_specification.json";
// Vertices nearer than this to the other garment's cloth are measured (a loose top stands off
// the skirt under it by a few centimetres).
constexpr double kNear = 0.05;

struct Sides {
  int near = 0;    // vertices of `outer` within kNear of `inner`'s cloth
  int inside = 0;  // of those, on the inside of their closest triangle by more than the tolerance
};

// Where the vertices of garment `outer` are with respect to the triangles of garment `inner`.
Sides sides(const Scene& scene, const Eigen::MatrixX3d& x, int inner, int outer) {
  const Garment& garment = *scene.garment;
  const OutfitGarment& in = scene.outfit[inner];
  const OutfitGarment& out = scene.outfit[outer];
  const auto of = [&](const OutfitGarment& part, int piece) {
    return piece >= part.first_piece && piece < part.first_piece + part.piece_count;
  };
  Sides result;
  for (int v = 0; v < garment.vertex_count(); ++v) {
    if (!of(out, garment.vertex_piece(v))) continue;
    const Eigen::Vector3d p = x.row(v).transpose();
    double best = kNear;
    double side = 0.0;
    for (int t = 0; t < garment.triangle_count(); ++t) {
      if (!of(in, garment.triangle_piece(t))) continue;
      const Eigen::Vector3d a = x.row(garment.triangles(t, 0)).transpose(),
                            b = x.row(garment.triangles(t, 1)).transpose(),
                            c = x.row(garment.triangles(t, 2)).transpose();
      const Eigen::Vector3d w = closest_point_weights(p, a, b, c);
      const Eigen::Vector3d closest = w[0] * a + w[1] * b + w[2] * c;
      const double distance = (p - closest).norm();
      if (distance < best) {
        best = distance;
        side = (p - closest).dot((b - a).cross(c - a).normalized());
      }
    }
    if (best < kNear) {
      ++result.near;
      if (side < -1e-4) ++result.inside;
    }
  }
  return result;
}

}  // namespace

class OutfitSessionTest : public QObject {
  Q_OBJECT
 private slots:
  void outerGarmentStaysOutsideTheInnerOne_data() {
    QTest::addColumn<bool>("tucked_in");
    QTest::newRow("top tucked in") << true;
    QTest::newRow("top worn over") << false;
  }

  void outerGarmentStaysOutsideTheInnerOne() {
    QFETCH(bool, tucked_in);
    const std::filesystem::path top = test::test_data(kTop), skirt = test::test_data(kSkirt);
    const auto scene =
        load_outfit_scene(tucked_in ? std::vector{top, skirt} : std::vector{skirt, top},
                          test::test_data("bodies/f_smpl_average_A40.obj"));
    const Garment& garment = *scene->garment;
    QCOMPARE(scene->outfit.size(), std::size_t(2));
    QCOMPARE(scene->outfit[0].name, std::string(tucked_in ? "gc_0022" : "gc_0340"));
    QCOMPARE(scene->outfit[0].piece_count + scene->outfit[1].piece_count,
             static_cast<int>(garment.pieces.size()));
    std::vector<int> piece_garment(garment.pieces.size());
    for (int g = 0; g < 2; ++g) {
      const OutfitGarment& part = scene->outfit[g];
      QVERIFY(!part.seed.pieces().empty());
      for (int piece : part.seed.pieces())
        QVERIFY(piece >= part.first_piece && piece < part.first_piece + part.piece_count);
      for (int p = part.first_piece; p < part.first_piece + part.piece_count; ++p) {
        piece_garment[p] = g;
        QVERIFY(garment.pieces[p].name.starts_with(part.name + ":"));
      }
    }

    Session session(scene);
    session.run();
    const SessionReport& report = session.report();
    QCOMPARE(report.order.size(), garment.pieces.size());
    const auto first_outer = std::find_if(report.order.begin(), report.order.end(),
                                          [&](int piece) { return piece_garment[piece] == 1; });
    QVERIFY(std::all_of(first_outer, report.order.end(),
                        [&](int piece) { return piece_garment[piece] == 1; }));
    QCOMPARE(report.outfit_seeds.size(), std::size_t(1));
    QCOMPARE(report.outfit_seeds[0].garment, 1);
    int inner_batches = 0;
    for (const BatchRecord& batch : report.batches)
      inner_batches += piece_garment[batch.pieces.front()] == 0;
    QCOMPARE(report.outfit_seeds[0].first_batch, inner_batches);

    const BodyReference body(scene->body->mesh);
    const GarmentMetrics metrics =
        GarmentChecker(garment, &body, expected_regions_from_names(garment))
            .measure(session.positions());
    const QualityVerdict verdict = judge_garment(garment, metrics);
    std::string failures;
    for (const QualityFailure& failure : verdict.failures)
      failures += failure.message + "; ";
    QVERIFY2(verdict.ok(), failures.c_str());
    QVERIFY(crossings_between_garments(piece_garment, metrics).empty());

    const Sides outer = sides(*scene, session.positions(), 0, 1);
    const Sides inner = sides(*scene, session.positions(), 1, 0);
    QVERIFY2(outer.near >= 100, std::to_string(outer.near).c_str());
    QVERIFY2(outer.inside == 0, (std::to_string(outer.inside) + " of " +
                                 std::to_string(outer.near) + " outer vertices inside")
                                    .c_str());
    QVERIFY2(inner.inside > 0, "the inner garment is never inside the outer one?");
  }

  // The recovery's reseed of a later garment: the session continues from the checkpoint before
  // that garment's seed with another of its seed candidates. The inner garment is kept as it was
  // there (every piece arranged, none of the outer one's), the outer one is seeded with the plan
  // asked for. (Whether that seed makes a better garment is the recovery's measure, not this.)
  void laterGarmentIsSeededAgainFromItsCheckpoint() {
    const auto scene = load_outfit_scene({test::test_data(kTop), test::test_data(kSkirt)},
                                         test::test_data("bodies/f_smpl_average_A40.obj"));
    const OutfitGarment& skirt = scene->outfit[1];
    QVERIFY2(skirt.seed_candidates.size() >= 2, "the skirt has one seed candidate only");
    QCOMPARE(skirt.seed_candidates.front().pieces(), skirt.seed.pieces());
    const SeedPlan other = skirt.seed_candidates[1];
    auto first = std::make_shared<Session>(scene);
    first->run();
    const std::size_t before_seed = first->checkpoint_before_outfit_seed(1);
    QCOMPARE(first->checkpoint_phase(before_seed), Phase::Select);

    SessionOptions options = first->options();
    options.outfit_seeds = {std::nullopt, other};
    Session again(*first, before_seed, options);
    const Eigen::MatrixX3d inner_before = again.positions();
    again.run();
    QCOMPARE(again.report().outfit_seeds.size(), std::size_t(1));
    QCOMPARE(again.report().outfit_seeds[0].seed.pieces(), other.pieces());
    QCOMPARE(again.report().seed.pieces(), first->report().seed.pieces());
    // Up to the skirt's seed nothing changed: the top's batches are the first pass's.
    const int top_batches = first->report().outfit_seeds[0].first_batch;
    QCOMPARE(again.report().outfit_seeds[0].first_batch, top_batches);
    for (int b = 0; b < top_batches; ++b)
      QCOMPARE(again.report().batches[b].pieces, first->report().batches[b].pieces);
    // The checkpoint resumed: every piece of the top arranged, none of the skirt's, and the
    // positions the new session started from.
    first->restore(before_seed);
    const SessionSnapshot at = first->snapshot();
    for (int p = 0; p < static_cast<int>(at.pieces.size()); ++p)
      QCOMPARE(at.pieces[p] == PieceState::Waiting, p >= skirt.first_piece);
    QVERIFY(first->positions() == inner_before);
  }
};

QTEST_GUILESS_MAIN(OutfitSessionTest)
#include "test_outfit.moc"
