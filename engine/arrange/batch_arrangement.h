#pragma once
// The three steps that arrange one batch of pieces (paper §7), each a solve over its own domain:
//   align                    Eq. 8 rigid placement of new pieces, then deformation + sewing +
//                            fixing over the batch and the seam neighbourhood, bending stiffened
//   remove body intersections the same plus body repulsion, switched on ring by ring from the
//                            sewing boundary (§7.2)
//   refine                   one-sided repulsion against the arranged triangles, default bending,
//                            then mild gravity, over the 16-ring domain (§7.3)
// An outfit's later garment is kept outside the garments before it in all three steps.
// The session decides the order and the revisits (termination.h).

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "engine/arrange/arrangement_context.h"
#include "engine/core/observer.h"
#include "engine/solver/chebyshev_solver.h"

namespace garment {

enum class ArrangeStep { Align, RemoveBodyIntersections, Refine };
const char* to_string(ArrangeStep step);

struct StepRecord {
  ArrangeStep step = ArrangeStep::Align;
  int visit = 0;       // 0 on the first visit
  int iterations = 0;  // solver iterations of the step (all its solves)
  double work = 0.0;   // free vertices × iterations of its solves (SolveReport::work)
  double seconds = 0.0;
  double final_energy = 0.0;
  bool cancelled = false;
};

// Called at the solver's batch boundaries with the current positions (for live display).
using IterateCallback = std::function<void(const Eigen::MatrixX3d&)>;

class BatchArrangement {
 public:
  // arranged: mask over pieces arranged before this batch.
  BatchArrangement(ArrangementContext& context, std::vector<int> pieces,
                   std::vector<bool> arranged);
  // The arranged set before the batch (mask over pieces).
  const std::vector<bool>& arranged_before() const { return arranged_; }

  const std::vector<int>& pieces() const { return pieces_; }
  // The batch's pieces as a mask, and the arranged set after the batch.
  std::vector<bool> batch_mask() const;

  // Places the pieces that have no position yet by Eq. 8, in batch order (each one aligned to the
  // arranged pieces and the batch pieces placed before it).
  void place_new_pieces(Eigen::MatrixX3d& positions);

  StepRecord run(ArrangeStep step, int visit, Eigen::MatrixX3d& positions, Observer* observer,
                 const IterateCallback& on_iterate = {});

  // Termination rule 3 (§7.4): adds the unarranged pieces sewn to the batch; returns false when
  // there are none. The new pieces are placed by the next place_new_pieces.
  bool grow();

  // Vertices of the batch (free in every step).
  const std::vector<int>& vertices() const { return vertices_; }

 private:
  struct Domain {
    ActiveSet active;
    std::vector<int> softly_fixed;  // arranged vertices held by F^ext
  };
  void update_rings();
  // Eq. 12 one-sided repulsion of the batch against the arranged triangles of its garment.
  void add_self_repulsion(Objective& objective) const;
  // An outfit's later garment: every free vertex of its own in `active` stays outside the
  // garments before it, in every step (their cloth is nowhere sewn to it).
  void add_outfit_repulsion(Objective& objective, const ActiveSet& active) const;
  // Keeps `repelled` outside `obstacles` (triangle ids) with the arrangement's self repulsion.
  void add_repulsion(Objective& objective, std::vector<int> repelled,
                     std::vector<int> obstacles) const;
  Domain domain(int rings_free, int rings_fixed_beyond) const;
  int solve_with(Objective& objective, int iterations, const char* stage,
                 Eigen::MatrixX3d& positions, Observer* observer, const IterateCallback& on_iterate,
                 StepRecord& record);

  ArrangementContext* context_;  // not owned; a pointer so that checkpoints can copy the batch
  std::vector<int> pieces_;
  std::vector<bool> arranged_;
  std::vector<bool> placed_;  // pieces with meaningful positions (arranged + placed batch pieces)
  std::vector<int> vertices_;
  std::vector<char> is_batch_vertex_, is_arranged_vertex_;
  std::vector<int> arranged_ring_;  // ring distance on the arranged side from the seam, -1 beyond
  std::vector<int> batch_ring_;     // ring distance inside the batch from the seam, -1 unreached
};

}  // namespace garment
