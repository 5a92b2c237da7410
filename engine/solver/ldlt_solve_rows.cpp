#include "engine/solver/ldlt_solve_rows.h"

namespace garment {

Eigen::MatrixX3d ldlt_solve_rows(const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& ldlt,
                                 const Eigen::MatrixX3d& rhs) {
  // L's strict lower triangle by columns (its unit diagonal is not stored), as Eigen keeps it.
  const Eigen::SparseMatrix<double>& lower = ldlt.matrixL().nestedExpression();
  const Eigen::Index n = rhs.rows();
  const int* starts = lower.outerIndexPtr();
  const int* ends = lower.innerNonZeroPtr();  // null when compressed
  const int* rows = lower.innerIndexPtr();
  const double* values = lower.valuePtr();
  const auto end_of = [&](Eigen::Index j) { return ends ? starts[j] + ends[j] : starts[j + 1]; };

  // The three columns side by side, so that one entry of L updates one cache line: x = P b.
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  RowMajor x(n, 3);
  const auto& permutation = ldlt.permutationP().indices();
  if (permutation.size() > 0) {
    for (Eigen::Index i = 0; i < n; ++i)
      x.row(permutation[i]) = rhs.row(i);
  } else {
    x = rhs;
  }
  // L y = x, forward by columns of L; Eigen skips a column whose value is zero, and so does this,
  // per column of x.
  for (Eigen::Index j = 0; j < n; ++j) {
    const double t0 = x(j, 0), t1 = x(j, 1), t2 = x(j, 2);
    const bool any0 = t0 != 0.0, any1 = t1 != 0.0, any2 = t2 != 0.0;
    if (!(any0 || any1 || any2)) continue;
    for (int k = starts[j], end = end_of(j); k < end; ++k) {
      if (rows[k] <= j) continue;
      double* target = &x(rows[k], 0);
      if (any0) target[0] -= t0 * values[k];
      if (any1) target[1] -= t1 * values[k];
      if (any2) target[2] -= t2 * values[k];
    }
  }
  // D⁻¹ as Eigen applies it: the inverse's entries, then a product.
  const Eigen::VectorXd& diagonal = ldlt.vectorD();
  for (Eigen::Index i = 0; i < diagonal.size(); ++i)
    x.row(i) *= 1.0 / diagonal[i];
  // Lᵀ z = y, backward: row i of Lᵀ is column i of L.
  for (Eigen::Index j = n - 1; j >= 0; --j) {
    double t0 = x(j, 0), t1 = x(j, 1), t2 = x(j, 2);
    for (int k = starts[j], end = end_of(j); k < end; ++k) {
      if (rows[k] <= j) continue;
      const double* source = &x(rows[k], 0);
      t0 -= values[k] * source[0];
      t1 -= values[k] * source[1];
      t2 -= values[k] * source[2];
    }
    x(j, 0) = t0;
    x(j, 1) = t1;
    x(j, 2) = t2;
  }
  // X = P⁻¹ z.
  Eigen::MatrixX3d solution(n, 3);
  if (permutation.size() > 0) {
    for (Eigen::Index i = 0; i < n; ++i)
      solution.row(i) = x.row(permutation[i]);
  } else {
    solution = x;
  }
  return solution;
}

}  // namespace garment
