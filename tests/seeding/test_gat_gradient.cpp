// The hand-derived backward pass of the graph attention network (gat_model.cpp) against central
// finite differences of the loss, on a random graph and on a real pattern's sewing graph.

#include <QtTest>

#include <random>

#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/gat_model.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

SeedGraph random_graph(int nodes, std::mt19937& generator) {
  std::normal_distribution<double> normal;
  SeedGraph graph;
  graph.node_features = Eigen::MatrixXd::NullaryExpr(
      nodes, kNodeFeatureCount, [&](Eigen::Index, Eigen::Index) { return normal(generator); });
  std::vector<std::array<int, 2>> edges;
  for (int i = 0; i < nodes; ++i)
    for (int j = 0; j < nodes; ++j)
      if (i != j && (i + j) % 3 != 0) edges.push_back({i, j});  // symmetric, node 0 well connected
  graph.edges.resize(static_cast<Eigen::Index>(edges.size()), 2);
  for (std::size_t e = 0; e < edges.size(); ++e)
    graph.edges.row(e) << edges[e][0], edges[e][1];
  graph.edge_features =
      Eigen::MatrixXd::NullaryExpr(graph.edges.rows(), kEdgeFeatureCount,
                                   [&](Eigen::Index, Eigen::Index) { return normal(generator); });
  for (int i = 0; i < nodes; ++i)
    graph.groups.push_back({i});
  return graph;
}

// Largest |analytic − numeric| relative to the gradient's largest entry.
double gradient_error(const GatModel& model, const GatInput& input, const std::vector<int>& labels,
                      const Eigen::VectorXd& class_weights) {
  Eigen::VectorXd analytic = Eigen::VectorXd::Zero(model.parameter_count());
  model.loss(input, labels, class_weights, &analytic);
  GatModel probe = model;
  const double step = 1e-6;
  double worst = 0.0;
  for (int k = 0; k < model.parameter_count(); ++k) {
    const double kept = probe.parameters(k);
    probe.parameters(k) = kept + step;
    const double up = probe.loss(input, labels, class_weights, nullptr);
    probe.parameters(k) = kept - step;
    const double down = probe.loss(input, labels, class_weights, nullptr);
    probe.parameters(k) = kept;
    worst = std::max(worst, std::abs((up - down) / (2.0 * step) - analytic(k)));
  }
  return worst / analytic.cwiseAbs().maxCoeff();
}

}  // namespace

class GatGradientTest : public QObject {
  Q_OBJECT
 private slots:
  void backwardMatchesFiniteDifferencesOnRandomGraph() {
    std::mt19937 generator(7);
    GatShape shape;
    shape.heads = 3;
    shape.head_width = 5;
    GatModel model(shape);
    model.initialise(11);
    // Non-trivial normalisation: the backward pass works on normalised features.
    model.normalisation.node_mean = Eigen::VectorXd::Constant(kNodeFeatureCount, 0.3);
    model.normalisation.node_scale = Eigen::VectorXd::Constant(kNodeFeatureCount, 1.7);
    const SeedGraph graph = random_graph(6, generator);
    const GatInput input = model.prepare(graph);
    QCOMPARE(input.edges.rows(), Eigen::Index{graph.edge_count() + 6});  // self loops added
    const std::vector<int> labels = {0, 1, 2, 3, 4, 6};
    Eigen::VectorXd class_weights(7);
    class_weights << 2.0, 1.5, 1.0, 1.0, 0.8, 0.8, 0.5;
    const double error = gradient_error(model, input, labels, class_weights);
    QVERIFY2(error < 1e-6, qPrintable(QString::number(error)));
  }

  void backwardMatchesFiniteDifferencesOnRealPattern() {
    // The shipped shape on the sewing graph of a skirt with a waistband (gc_0012).
    const Garment garment =
        build_garment(load_pattern(test::test_data("patterns/gc_0012_specification.json")));
    const SeedGraph graph = build_seed_graph(garment);
    GatModel model;
    model.initialise(5);
    const GatInput input = model.prepare(graph);
    std::vector<int> labels;
    for (int g = 0; g < graph.node_count(); ++g)
      labels.push_back(g % 7);
    const double error = gradient_error(model, input, labels, Eigen::VectorXd::Ones(7));
    QVERIFY2(error < 1e-6, qPrintable(QString::number(error)));
  }

  void probabilitiesAreDistributions() {
    std::mt19937 generator(3);
    GatModel model;
    model.initialise(1);
    const Eigen::MatrixXd probabilities =
        model.probabilities(model.prepare(random_graph(5, generator)));
    QCOMPARE(probabilities.rows(), Eigen::Index{5});
    QCOMPARE(probabilities.cols(), Eigen::Index{7});
    QVERIFY((probabilities.rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-12);
    QVERIFY(probabilities.minCoeff() > 0.0);
  }

  void initialisationIsReproducible() {
    GatModel a, b, c;
    a.initialise(42);
    b.initialise(42);
    c.initialise(43);
    QVERIFY(a.parameters == b.parameters);
    QVERIFY(a.parameters != c.parameters);
  }
};

QTEST_APPLESS_MAIN(GatGradientTest)
#include "test_gat_gradient.moc"
