#pragma once
// Piece selection (paper §6): which piece(s) to arrange next, given the pieces arranged so far.
// Single pieces are scored by the heuristic of Eq. 6; candidates whose connections to the arranged
// set continue smoothly along its sewing boundary are combined and scored as one piece (§6.2), as
// are two sewn to each other by two or more seams (the halves of a tube, a trouser leg's front and
// back); the best candidates fill a batch up to a vertex cap, so that small pieces are solved
// together.

#include <Eigen/Core>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/sewing_relationship.h"

namespace garment {

struct SelectionParameters {
  // Eq. 6 weights. The first term is a fraction in [0, 1]; pieces are 0.01–0.5 m², so s_a = 1/m²
  // lets a large piece outweigh a small one without overruling coverage; s_b = 2/m² favours pieces
  // well supported from the top (S of Eq. 1 is of the order of the piece's area below the seam).
  double area_weight = 1.0;     // s_a, 1/m²
  double support_weight = 2.0;  // s_b, 1/m²
  // Two sewing boundary edges of the arranged set meeting at a point continue "smoothly" when they
  // turn by less than this angle there (§6.2).
  double smooth_turn_degrees = 35.0;
  int batch_vertex_cap = 1024;  // §6.2
  // Combined candidates (smooth connections and tube halves, above); off, every candidate is one
  // piece: with a cap of one vertex, one piece per batch (bench_pipeline's batching ablation).
  bool combine = true;
};

struct Candidate {
  std::vector<int> pieces;  // one piece, or a combination (§6.2)
  double score = 0.0;       // H of Eq. 6
};

class Selector {
 public:
  Selector(const Garment& garment, SelectionParameters parameters = {});

  // Candidates sewn to `arranged` (a mask over pieces), combined where their connection to the
  // arranged set is continuous or where they close into a tube between them, best first. positions:
  // #V×3, current positions of arranged pieces.
  std::vector<Candidate> candidates(const std::vector<bool>& arranged,
                                    const Eigen::MatrixX3d& positions) const;

  // H(P) of Eq. 6 for a set of pieces treated as one.
  double score(const std::vector<bool>& arranged, const std::vector<int>& pieces) const;

  // The next batch: the best candidates until the batch holds batch_vertex_cap vertices (at least
  // one candidate). Every piece of a batch is sewn to the arranged set: a piece hanging only from
  // another piece of the batch (a cuff on a sleeve) waits for the next batch, when its partner has
  // a shape to be aligned to. Empty when nothing unarranged is sewn to the arranged set.
  std::vector<int> next_batch(const std::vector<bool>& arranged,
                              const Eigen::MatrixX3d& positions) const;

  const SewingRelationship& relationship() const { return relationship_; }

 private:
  const Garment& garment_;
  SelectionParameters parameters_;
  SewingRelationship relationship_;
  std::vector<double> areas_;
  Eigen::VectorXi welded_;
};

}  // namespace garment
