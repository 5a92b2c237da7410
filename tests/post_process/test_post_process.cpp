// The post-process on real garments, each through two sessions that are identical up to the
// post-process (one thread; checked) and differ in one of its parameters:
// - the strain limit (arrangement_parameters.h, stretch_potential.h) on a garment whose waistband
//   the plain springs left over-stretched: tests/data/patterns/gc_0473 (a skirt with a two-part
//   waistband) on its own body, m_smpl_average_A40, whose waist is wider than the body
//   measurements the pattern was cut for;
// - the body buffer and the repulsion of points along edges (body_edge_repulsion_potential.h),
//   on the same gc_0473: its snug waistband eases when it may lie closer to the body, and only
//   the edge repulsion keeps edges from cutting into the body there;
// - the untangling passes (untangle.h) on gc_0012, whose skirt panels cross at a side seam, and
//   none past their time bound; one solver iteration after each pass, not three, on gc_0282,
//   whose circle skirt's front crosses itself along a pleat; another round of passes after a
//   settle that brings the pieces back through each other, on gc_0318 (both on the bundled
//   body, mean_all);
// - the post-process's stiffer bending on basic_tee__tee, whose sleeves fold without it;
// - the leg separation (leg_tubes.h, side_barrier_potential.h) on gc_0431, trousers whose legs
//   reach into each other's side between the body's legs without it;
// - the two-sided self repulsion within a layer (own_cloth_repulsion.h) on gc_0195, a circle
//   skirt whose waistband folds through itself without it;
// - the longer settle of a garment narrowly over-stretched after the first iterations, on
//   gc_0279 (a skirt whose front waistband is left just past 20 % strain), and its absence on
//   gc_0195, which settles clean within them; and its end after one round on gc_0473 (judging
//   half, a fixed case), whose waistband closes too slowly to pass in the rounds left;
// - the round with stiffer bending of a garment left with folds at the end, on gc_0476 (a top
//   with a skirt of two panels, creased after the untangling);
// - the clearance kept from the body for a simulator (issue 44), on gc_0000, a pencil skirt.

#include <tbb/global_control.h>

#include <QtTest>

#include <algorithm>
#include <limits>
#include <tuple>
#include <utility>

#include "engine/body/default_body.h"
#include "engine/body/exact_body_distance.h"
#include "engine/core/mesh_topology.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"
#include "engine/session/session.h"
#include "support/test_environment.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

// Edge strains (|x_i − x_j| − L) / L over the garment's mesh edges, L from the rest pattern.
std::vector<double> edge_strains(const Garment& garment, const Eigen::MatrixX3d& positions) {
  const MeshEdges mesh = build_mesh_edges(garment.triangles, garment.vertex_count());
  std::vector<double> strains;
  for (Eigen::Index e = 0; e < mesh.edges.rows(); ++e) {
    const int i = mesh.edges(e, 0), j = mesh.edges(e, 1);
    const double rest = (garment.rest_positions.row(i) - garment.rest_positions.row(j)).norm();
    strains.push_back(((positions.row(i) - positions.row(j)).norm() - rest) / rest);
  }
  return strains;
}

struct Outcome {
  Eigen::MatrixX3d arranged;  // before the post-process
  Eigen::MatrixX3d final_positions;
  int post_process_iterations = 0;
  int untangle_passes = 0;
};

Outcome run(const std::shared_ptr<const Scene>& scene, const ArrangementParameters& parameters) {
  SessionOptions options;
  options.arrangement = parameters;
  Session session(scene, options);
  Outcome outcome;
  while (!session.done()) {
    if (session.phase() == Phase::PostProcess) outcome.arranged = session.positions();
    session.step();
  }
  outcome.final_positions = session.positions();
  outcome.post_process_iterations = session.report().post_process.iterations;
  outcome.untangle_passes = session.report().post_process.untangle_passes;
  return outcome;
}

// A pattern of tests/data/patterns on a body of tests/data/bodies.
std::shared_ptr<const Scene> data_scene(const std::string& pattern, const std::string& body) {
  return load_scene(test::test_data("patterns/" + pattern), test::test_data("bodies/" + body));
}

// The final garments of two outcomes, measured on the scene's body.
std::pair<GarmentMetrics, GarmentMetrics> measure_post_processed(const Scene& scene,
                                                                 const Outcome& first,
                                                                 const Outcome& second) {
  const BodyReference body(scene.body->mesh);
  const std::vector<ExpectedRegion> regions = expected_regions_from_names(*scene.garment);
  return {measure_garment(*scene.garment, first.final_positions, &body, regions),
          measure_garment(*scene.garment, second.final_positions, &body, regions)};
}

// A pattern of tests/data/patterns/untangle/ on the bundled body (mean_all), post-processed at
// the default parameters and with `change` made to them: both final garments measured and
// judged, and whether the two arrangements before the post-process were the same.
struct Untangled {
  GarmentMetrics by_default, otherwise;
  bool by_default_ok = false, otherwise_ok = false, same_arrangement = false;
};
template <class Change>
Untangled untangled_by_default_and_otherwise(const std::string& pattern, Change change) {
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const std::shared_ptr<const Scene> scene =
      load_scene(test::test_data("patterns/untangle/" + pattern), default_body_path());
  ArrangementParameters parameters;
  const Outcome by_default = run(scene, parameters);
  change(parameters);
  const Outcome otherwise = run(scene, parameters);
  Untangled result;
  std::tie(result.by_default, result.otherwise) =
      measure_post_processed(*scene, by_default, otherwise);
  result.by_default_ok = judge_garment(*scene->garment, result.by_default).ok();
  result.otherwise_ok = judge_garment(*scene->garment, result.otherwise).ok();
  result.same_arrangement = by_default.arranged == otherwise.arranged;
  return result;
}

}  // namespace

class PostProcessTest : public QObject {
  Q_OBJECT

 private slots:
  void strainLimitBringsOverstretchedEdgesBack() {
    // Two whole sessions at full budgets, a minute under the sanitizers for figures the Release
    // run checks; the sanitizers see the limited springs in every session's post-process
    // (session_session, ui_studio_session) and in energy_gradients.
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the strain figures are checked in the Release run");
    // One thread: both sessions arrange the garment identically before their post-processes.
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const std::shared_ptr<const Scene> scene =
        data_scene("gc_0473_specification.json", "m_smpl_average_A40.obj");
    ArrangementParameters parameters;
    parameters.post_process_untangle_passes = 0;  // the springs alone
    const Outcome limited = run(scene, parameters);
    parameters.post_process_strain_limit_factor = 1.0;
    const Outcome plain = run(scene, parameters);
    QVERIFY(plain.arranged.rows() == scene->garment->vertex_count());
    QCOMPARE(limited.arranged, plain.arranged);

    const auto over = [](const std::vector<double>& strains, double bar) {
      return std::count_if(strains.begin(), strains.end(), [&](double s) { return s > bar; });
    };
    const std::vector<double> plain_strains = edge_strains(*scene->garment, plain.final_positions);
    const std::vector<double> limited_strains =
        edge_strains(*scene->garment, limited.final_positions);
    const double plain_max = *std::max_element(plain_strains.begin(), plain_strains.end());
    const double limited_max = *std::max_element(limited_strains.begin(), limited_strains.end());
    qInfo("max edge strain %.3f without the limit, %.3f with it; edges over 20 %%: %td, %td",
          plain_max, limited_max, over(plain_strains, 0.2), over(limited_strains, 0.2));
    // The case the limit is for: plain springs leave edges past the quality bar of 20 %.
    QVERIFY(plain_max > 0.2);
    QVERIFY(limited_max < plain_max);
    QVERIFY(over(limited_strains, 0.2) < over(plain_strains, 0.2) / 2);
  }

  void closerBufferWithEdgeRepulsionEasesASnugBand() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the edge repulsion runs there in every session's post-process");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const std::shared_ptr<const Scene> scene =
        data_scene("gc_0473_specification.json", "m_smpl_average_A40.obj");
    ArrangementParameters parameters;
    parameters.post_process_untangle_passes = 0;
    // The edge repulsion on the garment it was measured on: with the leg separation on, this band
    // happens not to be cut into at 3 mm with vertices only (one edge of it was).
    parameters.post_process_leg_separation_factor = 0.0;
    // At the arrangement's bending: the post-process's stiffer bending alone keeps this band's
    // edges out of the body at 3 mm with vertices only.
    parameters.post_process_bending_factor = 1.0;
    // The arrangement it was measured after, lifting only the vertices placed inside the body: the
    // tapered lift leaves a band whose strain the closer buffer lowers at the top (max) but not
    // in its 99th percentile.
    parameters.lift_taper = std::numeric_limits<double>::infinity();
    const Outcome close = run(scene, parameters);  // 3 mm, edges held
    parameters.post_process_edge_repulsion_factor = 0.0;
    const Outcome vertices_only = run(scene, parameters);
    parameters.post_process_body_buffer = 0.004;
    const Outcome wide = run(scene, parameters);
    QCOMPARE(close.arranged, wide.arranged);
    QCOMPARE(vertices_only.arranged, wide.arranged);

    const BodyReference body(scene->body->mesh);
    const std::vector<ExpectedRegion> regions = expected_regions_from_names(*scene->garment);
    GarmentMetrics metrics[3];
    const Outcome* outcomes[3] = {&wide, &vertices_only, &close};
    for (int k = 0; k < 3; ++k)
      metrics[k] = measure_garment(*scene->garment, outcomes[k]->final_positions, &body, regions);
    qInfo(
        "buffer 4 mm: max strain %.3f, p99 %.3f, body crossing edges %d; 3 mm, vertices only: "
        "%.3f, %.3f, %d; 3 mm with edges: %.3f, %.3f, %d",
        metrics[0].max_strain, metrics[0].p99_strain, metrics[0].body_crossing_edges,
        metrics[1].max_strain, metrics[1].p99_strain, metrics[1].body_crossing_edges,
        metrics[2].max_strain, metrics[2].p99_strain, metrics[2].body_crossing_edges);
    // A band 1 mm closer round a ~93 cm waist is 6 mm shorter: under 1 % of strain, all of it
    // in the band.
    QVERIFY(metrics[0].max_strain > 0.2);
    QVERIFY(metrics[2].max_strain < metrics[0].max_strain);
    QVERIFY(metrics[2].p99_strain < metrics[0].p99_strain);
    // Only the edge repulsion keeps every edge out of the body (the band, stretched past the
    // strain limit at 4 mm, is pulled into the waist there too).
    QVERIFY(metrics[1].body_crossing_edges > 0);
    QCOMPARE(metrics[2].body_crossing_edges, 0);
  }

  void untanglingSeparatesPiecesThatCrossAfterTheSettle() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the untangling kernel runs there in post_process_untangle");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    // gc_0012 (a skirt in two panels and a two-part waistband) on f_smpl_average_A40: the front
    // and back panels, arranged in one batch, end the settle through each other at a side seam.
    const std::shared_ptr<const Scene> scene =
        data_scene("gc_0012_specification.json", "f_smpl_average_A40.obj");
    ArrangementParameters parameters;
    const Outcome untangled = run(scene, parameters);
    parameters.post_process_untangle_passes = 0;
    const Outcome settled = run(scene, parameters);
    QCOMPARE(untangled.arranged, settled.arranged);
    const auto [before, after] = measure_post_processed(*scene, settled, untangled);
    qInfo(
        "cloth edges crossing cloth: %d after the settle, %d untangled; seam gap %.1f mm, %.1f "
        "mm; body crossing edges %d, %d",
        before.self_crossing_edges, after.self_crossing_edges, 1000.0 * before.max_seam_gap_m,
        1000.0 * after.max_seam_gap_m, before.body_crossing_edges, after.body_crossing_edges);
    QVERIFY(before.self_crossing_edges > 0);
    QCOMPARE(after.self_crossing_edges, 0);
    // Pulled apart without tearing seams open or pushing cloth into the body.
    QVERIFY(after.max_seam_gap_m < 0.005);
    QCOMPARE(after.body_crossing_edges, 0);

    // Past the untangling work bound no pass starts: the garment stays as the settle left it.
    QVERIFY(untangled.untangle_passes > 0);
    parameters.post_process_untangle_passes = ArrangementParameters().post_process_untangle_passes;
    parameters.post_process_work = 0.0;
    const Outcome late = run(scene, parameters);
    QCOMPARE(late.untangle_passes, 0);
    QCOMPARE(late.final_positions, settled.final_positions);
  }

  void onePassAfterAnotherSeparatesAPleatThroughItself() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the untangling kernel runs there in post_process_untangle");
    // gc_0282 (tuning half): a fitted top with a circle skirt, whose front ends the settle through
    // itself along a pleat from the waist down. Three solver iterations after each pass pull the
    // pleat back through as fast as the passes push it out; one lets the passes win.
    const Untangled u = untangled_by_default_and_otherwise(
        "gc_0282_specification.json",
        [](auto& parameters) { parameters.post_process_untangle_iterations = 3; });
    qInfo("cloth edges crossing cloth: %d with one iteration a pass, %d with three",
          u.by_default.self_crossing_edges, u.otherwise.self_crossing_edges);
    QVERIFY(u.same_arrangement);
    QCOMPARE(u.by_default.self_crossing_edges, 0);
    QVERIFY(u.otherwise.self_crossing_edges > 0);
    QVERIFY(u.by_default_ok);
  }

  void aSettleThatCrossesAgainStartsAnotherRound() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the untangling kernel runs there in post_process_untangle");
    // gc_0318 (tuning half): a dress whose pieces the passes pull apart, and whose settle then
    // brings them back through each other. With one round it keeps the positions the passes
    // left, stretched past the verdict's limit; the next round starts from the settled cloth,
    // and that settle stays apart.
    const Untangled u = untangled_by_default_and_otherwise(
        "gc_0318_specification.json",
        [](auto& parameters) { parameters.post_process_untangle_rounds = 1; });
    qInfo("max strain %.1f %% after rounds, %.1f %% after one; cloth edges crossing cloth %d, %d",
          100.0 * u.by_default.max_strain, 100.0 * u.otherwise.max_strain,
          u.by_default.self_crossing_edges, u.otherwise.self_crossing_edges);
    QVERIFY(u.same_arrangement);
    QCOMPARE(u.otherwise.self_crossing_edges, 0);
    QVERIFY(u.otherwise.max_strain > 0.2);
    QVERIFY(u.by_default_ok);
  }

  void stifferBendingKeepsSqueezedSleevesFromFolding() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the bending kernel runs there in energy_gradients");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    // basic_tee__tee (Garment-Pattern-Generator) on f_smpl_average_A40: with the arrangement's
    // bending, its sleeves and back crease where gravity and the strain limit squeeze them.
    const std::shared_ptr<const Scene> scene =
        data_scene("basic_tee__tee.json", "f_smpl_average_A40.obj");
    ArrangementParameters parameters;
    parameters.post_process_fold_iterations = 0;  // its stiffer bending would smooth the creases
    const Outcome stiff = run(scene, parameters);
    parameters.post_process_bending_factor = 1.0;
    const Outcome soft = run(scene, parameters);
    QCOMPARE(stiff.arranged, soft.arranged);
    const auto [creased, smooth] = measure_post_processed(*scene, soft, stiff);
    qInfo(
        "folds: %d at the arrangement's bending, %d at the post-process's; seam gap %.1f mm, %.1f "
        "mm; max strain %.3f, %.3f",
        creased.folds, smooth.folds, 1000.0 * creased.max_seam_gap_m,
        1000.0 * smooth.max_seam_gap_m, creased.max_strain, smooth.max_strain);
    QVERIFY(creased.folds > 0);
    QCOMPARE(smooth.folds, 0);
    // Stiffer cloth that still closes its seams and keeps to the strain bound.
    QVERIFY(smooth.max_seam_gap_m < 0.005);
    QVERIFY(smooth.max_strain < 0.2);
  }

  void ownLayerRepulsionKeepsAWaistbandFromFoldingThroughItself() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the repulsion's kernel runs there in energy_gradients");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    // gc_0195 (a circle skirt and a straight waistband in two parts) on its body,
    // m_smpl_average_A40: the heavy skirt settling under gravity drags the back of the waistband,
    // its seed, down and over itself (without the repulsion, 19 folds in the waistband and 3
    // cloth edges crossing; with the earlier start of the skirt, 46 folds and 40 edges).
    const std::shared_ptr<const Scene> scene =
        data_scene("gc_0195_specification.json", "m_smpl_average_A40.obj");
    ArrangementParameters parameters;
    parameters.post_process_fold_iterations = 0;  // its stiffer bending would smooth the folds
    const Outcome repelled = run(scene, parameters);
    parameters.post_process_own_layer_repulsion_factor = 0.0;
    const Outcome free = run(scene, parameters);
    QCOMPARE(repelled.arranged, free.arranged);
    const auto [before, after] = measure_post_processed(*scene, free, repelled);
    qInfo(
        "cloth edges crossing cloth: %d without the repulsion within layers, %d with; folds %d, "
        "%d; seam gap %.1f mm, %.1f mm; max strain %.3f, %.3f",
        before.self_crossing_edges, after.self_crossing_edges, before.folds, after.folds,
        1000.0 * before.max_seam_gap_m, 1000.0 * after.max_seam_gap_m, before.max_strain,
        after.max_strain);
    QVERIFY(before.folds > 0);
    QCOMPARE(after.self_crossing_edges, 0);
    QCOMPARE(after.folds, 0);
    QVERIFY(after.max_seam_gap_m < 0.005);
    QVERIFY(after.max_strain < 0.2);
  }

  void legSeparationKeepsTrouserLegsApart() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the barrier's kernel runs there in energy_gradients");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    // gc_0431 on its body, m_smpl_average_A40: the legs' back panels meet across the plane of
    // symmetry below the crotch, where no body parts them.
    const std::shared_ptr<const Scene> scene =
        data_scene("gc_0431_specification.json", "m_smpl_average_A40.obj");
    ArrangementParameters parameters;
    // At the arrangement's bending: the post-process's stiffer bending alone keeps these legs to
    // within 8 mm of the plane (23 vertices across), a case the barrier is not needed for.
    parameters.post_process_bending_factor = 1.0;
    parameters.post_process_fold_iterations = 0;  // nor the round with stiffer bending
    // Darts at their strength before post_process_dart_factor (1): pulled as hard as seams, this
    // garment's darts close, and at the arrangement's bending the barrier then leaves stitches
    // 7.4 mm open and 4 edges through the body (at the default bending and fold round the whole
    // pipeline arranges it clean: the 500-pattern batch).
    parameters.post_process_dart_factor = 1.0;
    const Outcome separated = run(scene, parameters);
    parameters.post_process_leg_separation_factor = 0.0;
    const Outcome overlapping = run(scene, parameters);
    QCOMPARE(separated.arranged, overlapping.arranged);
    const auto [before, after] = measure_post_processed(*scene, overlapping, separated);
    qInfo(
        "cloth edges crossing cloth: %d without the barrier, %d with; seam gap %.1f mm, %.1f mm; "
        "max strain %.3f, %.3f; body crossing edges %d, %d",
        before.self_crossing_edges, after.self_crossing_edges, 1000.0 * before.max_seam_gap_m,
        1000.0 * after.max_seam_gap_m, before.max_strain, after.max_strain,
        before.body_crossing_edges, after.body_crossing_edges);
    // Without it the legs' panels (pant_*_r, pant_*_l) below the crotch reach across the plane of
    // symmetry into the other leg's side (70 vertices, by up to 6.8 mm) and cross each other (6
    // cloth edges); with it a quarter as many vertices do (17), by less than a centimetre (a
    // penalty, not a wall), nothing crosses and every stitch closes.
    const BodyLandmarks& landmarks = scene->body->landmarks;
    struct Across {
      int vertices = 0;  // more than 1 mm across
      double deepest = 0.0;
    };
    const auto across = [&](const Eigen::MatrixX3d& positions) {
      Across result;
      for (int v = 0; v < scene->garment->vertex_count(); ++v) {
        const std::string& name = scene->garment->pieces[scene->garment->vertex_piece(v)].name;
        if (!name.starts_with("pant_") || positions(v, 1) > landmarks.crotch - 0.03) continue;
        // The pattern's right leg is worn on the body's −x side.
        const bool right = name.ends_with("_r") || name.find("_r_") != std::string::npos;
        const double beyond = (right ? 1.0 : -1.0) * (positions(v, 0) - landmarks.centre_x);
        result.vertices += beyond > 0.001;
        result.deepest = std::max(result.deepest, beyond);
      }
      return result;
    };
    const Across without = across(overlapping.final_positions);
    const Across with = across(separated.final_positions);
    qInfo(
        "leg vertices across the plane: %d (up to %.1f mm) without the barrier, %d (%.1f mm) with",
        without.vertices, 1000.0 * without.deepest, with.vertices, 1000.0 * with.deepest);
    QVERIFY(before.self_crossing_edges > 0 || before.max_seam_gap_m > 0.005 ||
            before.body_crossing_edges > 0);
    QVERIFY(with.deepest < 0.01);
    QVERIFY(2 * with.vertices < without.vertices);
    QCOMPARE(after.self_crossing_edges, 0);
    // Every stitch closed. (The verdict's seam gap also counts dart mouths: at the darts' old
    // strength pinned above they stay 6.3-6.4 mm open with the barrier and without it.)
    QVERIFY(*std::max_element(after.stitch_max_gap_m.begin(), after.stitch_max_gap_m.end()) <
            0.005);
    QVERIFY(after.max_strain < 0.2);
    QCOMPARE(after.body_crossing_edges, 0);
  }
  void settlesLongerOnlyWhileNarrowlyStretchedOrOpen() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const ArrangementParameters defaults;
    const int first = defaults.post_process_iterations;
    const int extra = defaults.post_process_extra_iterations;
    QVERIFY(extra > 0);
    {
      // gc_0279 on its body, m_smpl_average_A40: a skirt of 14 panels under a waistband the first
      // iterations leave past the verdict's 20 % strain.
      const std::shared_ptr<const Scene> scene =
          data_scene("gc_0279_specification.json", "m_smpl_average_A40.obj");
      ArrangementParameters parameters;
      const Outcome longer = run(scene, parameters);
      parameters.post_process_extra_iterations = 0;
      const Outcome first_only = run(scene, parameters);
      QCOMPARE(longer.arranged, first_only.arranged);
      const auto [before, after] = measure_post_processed(*scene, first_only, longer);
      qInfo("max strain %.4f after %d iterations, %.4f after %d; seam gap %.1f mm, %.1f mm",
            before.max_strain, first_only.post_process_iterations, after.max_strain,
            longer.post_process_iterations, 1000.0 * before.max_seam_gap_m,
            1000.0 * after.max_seam_gap_m);
      QVERIFY(before.max_strain > 0.2 || before.max_seam_gap_m > 0.005);
      QCOMPARE(first_only.post_process_iterations, first);
      QVERIFY(longer.post_process_iterations > first);
      QVERIFY(longer.post_process_iterations <= first + extra);
      QVERIFY(after.max_strain <= 0.2);
      QVERIFY(after.max_seam_gap_m <= 0.005);
    }
    {
      // gc_0195 on m_smpl_average_A40 settles clean within the first iterations: no more.
      const std::shared_ptr<const Scene> scene =
          data_scene("gc_0195_specification.json", "m_smpl_average_A40.obj");
      const Outcome settled = run(scene, defaults);
      const auto [metrics, same] = measure_post_processed(*scene, settled, settled);
      QVERIFY(metrics.max_strain <= 0.2);
      QVERIFY(metrics.max_seam_gap_m <= 0.005);
      QCOMPARE(settled.post_process_iterations, first);
    }
  }

  // A seam that closes too slowly to pass in the rounds left ends the longer settle: gc_0473 on
  // its body, m_smpl_average_A40 (a fixed case of the judging half, tests/data), whose skirt
  // waistband stays just past the limits however long it settles.
  void aSettleTooSlowToPassStopsEarly() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const std::shared_ptr<const Scene> scene =
        data_scene("gc_0473_specification.json", "m_smpl_average_A40.obj");
    ArrangementParameters parameters;
    const Outcome paced = run(scene, parameters);
    parameters.post_process_paced_settle = false;
    const Outcome unpaced = run(scene, parameters);
    QCOMPARE(paced.arranged, unpaced.arranged);
    const auto [at_pace, at_length] = measure_post_processed(*scene, paced, unpaced);
    qInfo("paced: %d iterations, strain %.4f, gap %.1f mm; unpaced: %d, %.4f, %.1f mm",
          paced.post_process_iterations, at_pace.max_strain, 1000.0 * at_pace.max_seam_gap_m,
          unpaced.post_process_iterations, at_length.max_strain, 1000.0 * at_length.max_seam_gap_m);
    QVERIFY(paced.post_process_iterations < unpaced.post_process_iterations);
    // Settled all the way it fails all the same.
    QVERIFY(at_length.max_strain > 0.2 || at_length.max_seam_gap_m > 0.005);
  }

  void foldsLeftAtTheEndSettleWithStifferBending() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    // gc_0476 (tuning half; a top with a skirt of two panels) on its body, the bundled mean_all:
    // it ends the first settle and the untangling with 8 folds and cloth through cloth.
    const std::shared_ptr<const Scene> scene = load_scene(
        test::test_data("patterns/fold_round/gc_0476_specification.json"), default_body_path());
    ArrangementParameters parameters;
    parameters.revisit_work = 1e18;  // every revisit and every round, whatever the default budgets
    parameters.post_process_work = 1e18;
    const Outcome with_round = run(scene, parameters);
    parameters.post_process_fold_iterations = 0;
    const Outcome without = run(scene, parameters);
    QCOMPARE(with_round.arranged, without.arranged);
    const auto [before, after] = measure_post_processed(*scene, without, with_round);
    qInfo("%d folds after %d iterations, %d after %d", before.folds,
          without.post_process_iterations, after.folds, with_round.post_process_iterations);
    QVERIFY(before.folds > 0);
    QCOMPARE(after.folds, 0);
    QVERIFY(with_round.post_process_iterations > without.post_process_iterations);
    QVERIFY(judge_garment(*scene->garment, after).ok());
  }

  void clearanceKeepsTheClothFromTheBody() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    // gc_0000 (a pencil skirt in two panels) on f_smpl_average_A40, by default and with a
    // clearance of kClearance: the arrangement is the same, only the post-process moves the cloth
    // out. The bound is measured with the exact distance to the body's triangles, not with the
    // distance grid the repulsion samples.
    const std::shared_ptr<const Scene> scene =
        data_scene("gc_0000_specification.json", "f_smpl_average_A40.obj");
    ArrangementParameters parameters;
    const Outcome close = run(scene, parameters);
    parameters.clearance = kClearance;
    const Outcome clear = run(scene, parameters);
    QCOMPARE(clear.arranged, close.arranged);
    const ExactBodyDistance body(scene->body->mesh);
    const auto nearest = [&](const Outcome& outcome) {
      double nearest = std::numeric_limits<double>::infinity();
      for (Eigen::Index v = 0; v < outcome.final_positions.rows(); ++v)
        nearest =
            std::min(nearest, body.signed_distance(outcome.final_positions.row(v).transpose()));
      return nearest;
    };
    const double by_default = nearest(close), with_clearance = nearest(clear);
    qInfo("closest vertex to the body: %.2f mm by default, %.2f mm with a clearance of %.0f mm",
          1000.0 * by_default, 1000.0 * with_clearance, 1000.0 * kClearance);
    QVERIFY(by_default < kBound);  // the bound fails without the clearance
    QVERIFY(with_clearance >= kBound);
    const auto [before, after] = measure_post_processed(*scene, close, clear);
    QVERIFY(judge_garment(*scene->garment, before).ok());
    QVERIFY(judge_garment(*scene->garment, after).ok());
  }

 private:
  // The repulsion is a penalty: cloth that seams and gravity pull towards the body ends a little
  // inside its buffer (9.75 mm here; 5.74 and 11.70 mm for gc_0004 at 6 and 12 mm).
  static constexpr double kClearance = 0.01;
  static constexpr double kBound = kClearance - 0.001;
};

QTEST_GUILESS_MAIN(PostProcessTest)
#include "test_post_process.moc"
