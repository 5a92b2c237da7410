// The post-process's strain limit (arrangement_parameters.h, stretch_potential.h) on a garment
// whose waistband the plain springs left over-stretched: tests/data/patterns/gc_0473 (a skirt with
// a two-part waistband) on its own body, m_smpl_average_A40, whose waist is wider than the body
// measurements the pattern was cut for. Two sessions with the same parameters up to the
// post-process, one with the limit off, from the same arranged garment.

#include <tbb/global_control.h>

#include <QtTest>

#include "engine/arrange/session.h"
#include "engine/core/mesh_topology.h"
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
};

Outcome run(const std::shared_ptr<const Scene>& scene, double limit_factor) {
  SessionOptions options;
  options.arrangement.post_process_strain_limit_factor = limit_factor;
  Session session(scene, options);
  Outcome outcome;
  while (!session.done()) {
    if (session.phase() == Phase::PostProcess) outcome.arranged = session.positions();
    session.step();
  }
  outcome.final_positions = session.positions();
  return outcome;
}

}  // namespace

class PostProcessTest : public QObject {
  Q_OBJECT

 private slots:
  void strainLimitBringsOverstretchedEdgesBack() {
    // Two whole sessions at full budgets, a minute under the sanitizers for figures the Release
    // run checks; the sanitizers see the limited springs in every session's post-process
    // (arrange_session, ui_studio_session) and in energy_gradients.
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: the strain figures are checked in the Release run");
    // One thread: both sessions arrange the garment identically before their post-processes.
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const std::shared_ptr<const Scene> scene =
        load_scene(test::test_data("patterns/gc_0473_specification.json"),
                   test::test_data("bodies/m_smpl_average_A40.obj"));
    const Outcome plain = run(scene, 1.0);
    const Outcome limited = run(scene, ArrangementParameters{}.post_process_strain_limit_factor);
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
    QVERIFY(limited_max < plain_max - 0.05);
    QVERIFY(over(limited_strains, 0.2) < over(plain_strains, 0.2) / 2);
  }
};

QTEST_GUILESS_MAIN(PostProcessTest)
#include "test_post_process.moc"
