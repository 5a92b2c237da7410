#pragma once
// Termination checks of an arranged batch (paper §7.4, Eq. 13):
//   θ_in  = min n(t0)·n(t1) over neighbour triangles inside the batch's pieces   (folding)
//   θ_out = min n(t0)·n(t1) over triangle pairs made neighbours by the batch's seams, where the
//           sewn surface is consistently oriented                                  (sharp seam
//           fold)
//   s_max = max (|x_i − x_j| − L_ij) / L_ij over the springs of the batch's pieces (over-stretch)
// and the decision they lead to.

#include <Eigen/Core>
#include <vector>

#include "engine/arrange/arrangement_parameters.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

struct BatchCheck {
  double theta_in = 1.0;
  double theta_out = 1.0;
  double max_strain = 0.0;
};

enum class Revisit {
  None,     // accept the batch
  Flatten,  // θ_in below threshold: more iterations until flat
  Seam,     // θ_out below threshold: revisit once
  Grow,     // s_max above threshold: grow the batch by its neighbours, revisit once
};
const char* to_string(Revisit revisit);

class TerminationCheck {
 public:
  explicit TerminationCheck(const Garment& garment);

  // batch: mask over pieces; positions #V×3.
  BatchCheck measure(const std::vector<bool>& batch, const Eigen::MatrixX3d& positions) const;

  // The paper's rules, each revisit kind bounded: flatten up to max_flatten_revisits times, the
  // seam and grow revisits once per batch.
  static Revisit decide(const BatchCheck& check, const ArrangementParameters& parameters,
                        int flatten_revisits, bool seam_revisited, bool grown);

 private:
  const Garment& garment_;
  std::vector<Eigen::Vector2i> interior_pairs_;  // neighbour triangles inside a piece
  std::vector<Eigen::Vector2i> seam_pairs_;      // neighbour triangles across a consistent seam
  Eigen::MatrixX2i springs_;                     // mesh edges
  Eigen::VectorXd rest_lengths_;
};

}  // namespace garment
