#pragma once
// The common shape of every energy term (in the manner of ipc-toolkit's potentials): a potential
// owns a list of elements (springs, bending stencils, vertices, contacts) and selects the ones that
// take part for an ActiveSet (bind). It then contributes in one of two ways:
//   - quadratic potentials (is_quadratic: bending, sewing, fixing, gravity, upward) add their
//     constant K and linear b once per bind (add_quadratic_terms, see quadratic_terms.h);
//   - all others add the value, gradient and Hessian diagonal of any range of their selected
//     elements into caller-owned buffers (accumulate). The Assembler splits the ranges over
//     threads and gives every thread its own buffers, so accumulate never races.
// The per-element formulas are small stateless kernels in each potential's .cpp, with the paper
// equation cited.
//
// Positions inside the energy code are row-major (#V×3, x y z of a vertex adjacent in memory): the
// kernels gather and scatter whole vertices, and a column-major matrix would touch three cache
// lines per vertex. The public entry points (Objective, solve) take Eigen::MatrixX3d and convert.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/energy/active_set.h"
#include "engine/energy/quadratic_terms.h"

namespace garment {

using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;  // #V×3

// Where a range of elements adds its derivatives: per vertex six doubles, the gradient then the
// Hessian diagonal (interleaved, so that one cache line holds both). wants_diagonal is false when
// the caller needs no diagonal this time (see DiagonalKind). Rows of vertices that are not free
// may be written; the caller ignores them.
struct Accumulator {
  double* rows = nullptr;  // #V×6
  bool wants_diagonal = true;

  Eigen::Map<Eigen::Vector3d> gradient_row(int vertex) const {
    return Eigen::Map<Eigen::Vector3d>(rows + 6 * static_cast<std::ptrdiff_t>(vertex));
  }
  Eigen::Map<Eigen::Vector3d> diagonal_row(int vertex) const {
    return Eigen::Map<Eigen::Vector3d>(rows + 6 * static_cast<std::ptrdiff_t>(vertex) + 3);
  }
};

// How often the Jacobi preconditioner needs a potential's Hessian diagonal.
enum class DiagonalKind {
  Constant,  // independent of x: once per bind
  Current,   // depends on x: every evaluation. (Reusing a diagonal for a few iterations was
             // tried for the springs: when contacts stretch them fast, the stale transverse
             // stiffness lets steps explode.)
};

class Potential {
 public:
  virtual ~Potential() = default;

  virtual const char* name() const = 0;

  // Selects the elements that take part under `active` (ActiveSet::includes: no vertex outside
  // the problem, at least one free) and precomputes what does not change between evaluations.
  void bind(const ActiveSet& active);
  bool is_bound_to(const ActiveSet& active) const {
    return bound_generation_ == active.generation() && bound_revision_ == revision_;
  }

  // Called once per evaluation, before any accumulate, with the whole state: for quantities that
  // couple all elements (centroids, vertex normals) or are refreshed every few iterations
  // (closest triangles). `iteration` counts evaluations since the solve began (0 = first).
  // Returns true when the energy landscape itself changed (new contacts), so that the solver
  // does not read the change as an energy rise.
  virtual bool begin_evaluation(const Positions& x, int iteration) {
    (void)x;
    (void)iteration;
    return false;
  }

  // Number of selected elements after bind (and after begin_evaluation for contact potentials).
  virtual int element_count() const = 0;

  // Quadratic potentials: adds K and b of the selected elements (once per bind).
  virtual bool is_quadratic() const { return false; }
  virtual void add_quadratic_terms(QuadraticTerms& terms) const { (void)terms; }

  // Other potentials: adds the gradient (and the Hessian diagonal when out.wants_diagonal is
  // set) of the selected elements [begin, end) and returns their energy. Safe to call
  // concurrently on disjoint ranges with distinct accumulators.
  virtual double accumulate(const Positions& x, int begin, int end, const Accumulator& out) const {
    (void)x, (void)begin, (void)end, (void)out;
    return 0.0;
  }
  virtual DiagonalKind diagonal_kind() const { return DiagonalKind::Current; }

  // Other potentials: adds a scalar matrix that couples the vertices of each selected element as
  // its Hessian does at x (the springs' Laplacian weighted by their stiffness there), for the
  // quasi-Newton solver's preconditioner (quasi_newton_solver.h). Every call adds the same
  // entries, only their values change. Default: nothing, the solver then sees only the
  // potential's Hessian diagonal.
  virtual void add_preconditioner_terms(const Positions& x, QuadraticTerms& terms) const {
    (void)x, (void)terms;
  }

  // Marks every vertex an element may write (superset allowed); sized #V.
  virtual void mark_touched_vertices(std::vector<char>& touched) const = 0;

  // Bytes of element data one evaluation streams through (for the benchmark's bandwidth bound);
  // quadratic potentials stream nothing of their own (the Assembler's K does).
  virtual std::size_t element_bytes() const { return 0; }

 protected:
  // Every setter that changes elements or stiffness calls this, so that the next evaluation
  // rebinds.
  void changed() { revision_ = next_revision(); }
  virtual void bind_elements(const ActiveSet& active) = 0;

 private:
  static std::uint64_t next_revision();
  std::uint64_t revision_ = next_revision();
  std::uint64_t bound_revision_ = 0;
  std::uint64_t bound_generation_ = 0;
};

}  // namespace garment
