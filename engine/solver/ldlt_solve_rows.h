#pragma once
// Solves A X = B for the three columns of B (one row per free vertex) with the factors of an
// Eigen SimplicialLDLT of A, in one pass over L per triangular solve. Eigen's own solve makes one
// pass per column, and when L does not fit in the cache each pass streams all of it from memory
// (a garment's post-process: L of millions of entries, the solve a fifth of the run in perf on
// gc_0440). Each column gets the same operations in the same order as in Eigen's solve, so X is
// the same to the bit (tests/solver/test_ldlt_solve_rows.cpp).

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

namespace garment {

// ldlt: factorised (info() == Success); rhs: #N×3. Returns #N×3.
Eigen::MatrixX3d ldlt_solve_rows(const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& ldlt,
                                 const Eigen::MatrixX3d& rhs);

}  // namespace garment
