#pragma once
// The garment's openings and the body inside them. An opening is a closed boundary loop of the
// sewn garment: a neckline, a cuff's or a trouser leg's end, a waistband's top edge, a hem. Its
// rest length bounds how far round it can reach without stretching; a part of the body passing
// through it needs at least its girth there. When the girth is more than the rest length, the
// cloth along the opening must stretch by at least their ratio wherever the opening sits at that
// place: a design fault (a cuff narrower than the arm, a waistband smaller than the waist), which
// no arrangement can fix without moving the opening to a thinner part of the body.
//
// A seam round the body is an opening too, seen from the cloth on one side of it: a gathered
// seam (a cuff skirt's 17.7 cm top sewn to a sleeve end of 37.8 cm, gc_0014) closes to the
// shorter side, which must go round the arm however the longer side gathers.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/core/mesh_topology.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

struct Opening {
  // The loop in order, one garment vertex per point (the start of each boundary edge): #L ids.
  std::vector<int> vertices;
  std::vector<int> pieces;     // the pieces it runs along, ascending
  double rest_length_m = 0.0;  // sum of its edges' rest lengths
  // A seam ring: the loop is sewn all along to pieces outside `pieces` (their side of the seam,
  // whose rest length it has), not free cloth.
  bool seam = false;
};

// The closed boundary loops of the garment with every vertex class of `welded` (#V, e.g.
// weld_seams_and_darts) made one point: piece boundary edges that no other boundary edge meets
// after welding. Boundary paths that do not close (a non-manifold junction) are left out.
// Then the seam rings: the closed loops along which one piece, or two pieces sewn to each other
// (a sleeve's front and back, a cuff's), are sewn all round to the rest of the garment.
// mesh: build_mesh_edges of the garment's triangles.
std::vector<Opening> garment_openings(const Garment& garment, const MeshEdges& mesh,
                                      const Eigen::VectorXi& welded);

// How messages name an opening: "the opening along a, b", or for a seam ring "the seam round
// a, b" (the pieces of its side, ascending ids).
std::string opening_label(const Garment& garment, const std::vector<int>& pieces, bool seam);

// What a tape round the body inside the opening reads: the body's section by the opening's
// least-squares plane, keeping the points whose projection falls inside the projected loop (even
// odd rule), measured as the perimeter of their convex hull. 0 when no body is inside. Any closed
// curve round those points is at least this long, so the loop's current length is too.
// positions: #V×3 garment state.
double body_girth_inside(const Opening& opening, const Eigen::MatrixX3d& positions,
                         const BodyMesh& body);

}  // namespace garment
