#pragma once
// Initial alignment of a newly selected piece to the pieces already placed (paper §7.1, Eq. 8): the
// transform of the piece's rest shape that minimises the sewing gap to its placed partners, in
// closed form. We fit a rotation and translation (the shape-matching solution of Müller et al.
// 2005) rather than a general affine map, so that the piece is never mirrored or sheared, and add
// one "continuation" correspondence per sewing pair: a point a few centimetres inside the piece
// should land a few centimetres beyond the seam, continuing the partner's surface. That fixes the
// rotation about a straight seam, which sewing pairs alone leave free, and puts the piece's outside
// on the partner's outside. With fewer than two distinct pairs the paper's fallback applies:
// translation only.

#include <Eigen/Core>
#include <vector>

#include "engine/body/distance_grid.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

struct RigidTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  int sewing_pairs = 0;  // pairs the fit used
};

// Weighted least-squares rotation + translation taking `source` (#N×3) onto `target` (#N×3).
RigidTransform fit_rigid(const Eigen::MatrixX3d& source, const Eigen::MatrixX3d& target,
                         const Eigen::VectorXd& weights);

// Where each vertex of a piece is sewn to: the mean position of its partners on placed pieces.
struct SeamPartners {
  Eigen::MatrixX3d means;   // #piece vertices × 3 (piece-local rows); meaningful where counts > 0
  std::vector<int> counts;  // per piece vertex: its partners on placed pieces, 0 off the seam
};

// piece's partners on the pieces with placed[p] = true; positions: #V×3.
SeamPartners seam_partners(const Garment& garment, int piece, const std::vector<bool>& placed,
                           const Eigen::MatrixX3d& positions);

class PieceAligner {
 public:
  explicit PieceAligner(const Garment& garment);

  // The transform placing `piece` onto its sewing partners among the pieces with placed[p] = true.
  // positions: #V×3, meaningful for the placed pieces.
  RigidTransform fit(int piece, const std::vector<bool>& placed,
                     const Eigen::MatrixX3d& positions) const;

  // Writes the transformed rest shape of `piece` into its rows of positions.
  void place(int piece, const RigidTransform& transform, Eigen::MatrixX3d& positions) const;

  // A flat piece sewn on two sides of the body (a skirt front between the side seams, a sleeve
  // half around the arm) is placed through it. Lifts every vertex of `piece` that is inside the
  // body, or nearer than `clearance`, along its outside direction (its row of `outsides`, #V×3:
  // for a placed rest shape rotation · +z, which the continuation points made agree with its
  // partners' outside) until it is `clearance` away: the piece then drapes over the body instead
  // of crossing it. Vertices that find no way out within a metre stay where they are. The cloth
  // round a lifted vertex goes with it, tapering off by `taper` metres of lift per metre of
  // pattern distance: lifting the inside vertices alone leaves their neighbours where they were,
  // so that a skirt back tilted through both legs came out as cloth pulled back round each leg
  // and forward into the gap between them, stretched three times over (infinity: no taper).
  void lift_out_of_body(int piece, const Eigen::MatrixX3d& outsides, const DistanceGrid& body,
                        double clearance, double taper, Eigen::MatrixX3d& positions) const;

 private:
  const Garment& garment_;
  // For outline vertices: the previous and next outline vertex of the same piece, else -1.
  std::vector<int> outline_previous_, outline_next_;
};

}  // namespace garment
