#pragma once
// Post-process (paper §4): a quasistatic simulation of the whole arranged garment with stronger
// sewing and repulsion and full gravity, which closes the seams and removes the intersections the
// arrangement left. Cloth-cloth repulsion follows the arrangement order: every batch stays outside
// the pieces arranged before it (the inside-outside relation the order established, §7.3). Pieces
// that still cross each other after that (within one batch, where there is no order) are then
// untangled along their intersection contours (untangle.h).

#include <Eigen/Core>
#include <vector>

#include "engine/arrange/arrangement_context.h"
#include "engine/arrange/batch_arrangement.h"
#include "engine/core/observer.h"

namespace garment {

struct PostProcessReport {
  int iterations = 0;  // solver iterations, the untangling's included
  // Cloth-cloth contacts (edge, triangle) when the last untangling began (a creased garment is
  // untangled again after its round of stiffer bending) and at its last pass, and the passes
  // made in all.
  int initial_contacts = 0, final_contacts = 0, untangle_passes = 0;
  double work = 0.0;  // free vertices × solver iterations (SolveReport::work)
  double seconds = 0.0;
  double final_energy = 0.0;
};

// arranged: mask over pieces (waiting pieces stay out of the simulation). layers: the pieces of
// each batch in arrangement order, the seed's first. work_before: the session's work so far,
// which counts against parameters.post_process_work.
PostProcessReport post_process(ArrangementContext& context,
                               const std::vector<std::vector<int>>& layers, double work_before,
                               const std::vector<bool>& arranged, Eigen::MatrixX3d& positions,
                               Observer* observer, const IterateCallback& on_iterate = {});

}  // namespace garment
