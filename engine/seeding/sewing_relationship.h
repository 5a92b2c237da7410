#pragma once
// The sewing-relationship score of the paper's Eq. 1, S_{P→P'} = Σ_{e'∈∂P'} C(e', P) U(e'): how
// much of piece P' lies beneath the seams that join it to P, in P''s upright rest frame. A large
// S_{P→P'} means that P sits on top of P' (a waistband over a skirt, a collar over a bodice). The
// seeding classifier uses it as a feature; the selection heuristic (Eq. 6) reuses it, with P the
// set of pieces arranged so far.

#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment {

class SewingRelationship {
 public:
  explicit SewingRelationship(const Garment& garment);

  // S_{from→to} in m². `from` is a mask over pieces (#pieces); an outline edge e' of `to` counts
  // when both its vertices are sewn (Garment::sewing_pairs, darts excluded) to pieces in `from`
  // (C of Eq. 2), weighted by U(e'), the area of `to` in the column directly beneath e'.
  double score(const std::vector<bool>& from, int to) const;
  // Sets of pieces on both sides: Σ over the pieces of `to` of score(from, ·).
  double score(const std::vector<int>& from, const std::vector<int>& to) const;
  // One piece to one piece: S_{from→to}.
  double score(int from, int to) const { return score(mask({from}), to); }

  // Rest length (m) of the outline edges of `to` whose two vertices are both sewn to `from`.
  double sewn_length(const std::vector<bool>& from, int to) const;
  // Rest length (m) of the outline edges of `piece` that are sewn to any other piece: ∂P of the
  // paper (the denominator of Eq. 6's first term).
  double sewing_boundary_length(int piece) const;
  double outline_length(int piece) const;

  int piece_count() const { return static_cast<int>(outline_edges_.size()); }
  std::vector<bool> mask(const std::vector<int>& pieces) const;

 private:
  struct OutlineEdge {
    int start = 0, end = 0;    // global vertex ids
    double length = 0.0;       // rest length, m
    double column_area = 0.0;  // U(e'), m²
  };
  bool sewn_to(int vertex, const std::vector<bool>& from) const;

  std::vector<std::vector<OutlineEdge>> outline_edges_;  // per piece, counter-clockwise
  std::vector<std::vector<int>> vertex_partner_pieces_;  // #V pieces each vertex is sewn to
};

}  // namespace garment
