// ldlt_solve_rows (engine/solver/ldlt_solve_rows.h) gives, to the bit, what Eigen's
// SimplicialLDLT::solve gives for the same three columns: on a mesh's sparsity (the two-rectangle
// test pattern meshed at 1 cm, AMD-ordered as the solver does), for right-hand sides of every
// sign, and with a whole column and single entries zero (Eigen's forward pass skips those).

#include <QtTest>

#include <cstring>
#include <random>

#include "engine/core/mesh_topology.h"
#include "engine/solver/ldlt_solve_rows.h"
#include "support/flat_garment.h"

using namespace garment;

namespace {

using Ldlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;

// A mass-spring-like SPD matrix on the mesh's edges: weights w > 0 off the diagonal as −w, the
// diagonal their sum plus a mass, so that it is strictly diagonally dominant.
Eigen::SparseMatrix<double> mesh_matrix(const Garment& garment, std::mt19937& random) {
  const MeshEdges edges = build_mesh_edges(garment.triangles, garment.vertex_count());
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd diagonal = Eigen::VectorXd::Constant(garment.vertex_count(), 0.1);
  for (Eigen::Index e = 0; e < edges.edges.rows(); ++e) {
    const int a = edges.edges(e, 0), b = edges.edges(e, 1);
    const double w = weight(random);
    triplets.emplace_back(a, b, -w);
    triplets.emplace_back(b, a, -w);
    diagonal[a] += w;
    diagonal[b] += w;
  }
  for (int v = 0; v < garment.vertex_count(); ++v)
    triplets.emplace_back(v, v, diagonal[v]);
  Eigen::SparseMatrix<double> matrix(garment.vertex_count(), garment.vertex_count());
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

bool same_bits(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b) {
  return a.rows() == b.rows() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

}  // namespace

class LdltSolveRowsTest : public QObject {
  Q_OBJECT
 private slots:
  void equalsEigensSolveOnAMesh() {
    std::mt19937 random(7);
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.01);
    QVERIFY(garment.vertex_count() > 1000);
    Ldlt ldlt(mesh_matrix(garment, random));
    QCOMPARE(ldlt.info(), Eigen::Success);
    QVERIFY(ldlt.permutationP().size() == garment.vertex_count());

    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::MatrixX3d rhs(garment.vertex_count(), 3);
    for (Eigen::Index i = 0; i < rhs.size(); ++i)
      rhs.data()[i] = normal(random);
    const Eigen::MatrixX3d expected = ldlt.solve(rhs);
    QVERIFY(same_bits(ldlt_solve_rows(ldlt, rhs), expected));
    // And it solves the system (the comparison above would pass for two equal wrong answers).
    QVERIFY((ldlt.matrixL() * (ldlt.vectorD().asDiagonal() *
                               (ldlt.matrixU() * (ldlt.permutationP() * expected))) -
             ldlt.permutationP() * rhs)
                .norm() < 1e-9 * rhs.norm());

    // Zeros: a whole column, and scattered entries (Eigen skips a zero in its forward pass).
    rhs.col(1).setZero();
    for (Eigen::Index i = 0; i < rhs.rows(); i += 3)
      rhs(i, 2) = 0.0;
    QVERIFY(same_bits(ldlt_solve_rows(ldlt, rhs), ldlt.solve(rhs)));
    rhs.setZero();
    rhs(rhs.rows() / 2, 0) = 1.0;
    QVERIFY(same_bits(ldlt_solve_rows(ldlt, rhs), ldlt.solve(rhs)));
  }
};

QTEST_APPLESS_MAIN(LdltSolveRowsTest)
#include "test_ldlt_solve_rows.moc"
