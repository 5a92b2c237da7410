#pragma once
// Artifact metrics of a garment state (DESIGN.md "Quality", paper §7.4 and §8.3): what the report
// prints, what the verdict judges, and what the arrangement's termination checks read. A checker
// is built once per garment (topology, rest lengths, welded seams) and per body (AABB tree, axes),
// then measures any number of states: cheap enough to run after every batch.
//
// Definitions (E = edges of the unwelded pieces, the springs; "welded" = sewing and dart pairs
// joined, so that triangles meeting at a seam or a dart are adjacent):
//   body_inside_vertices  cloth vertices strictly inside the body (exact ray parity); depth = their
//                         distance to the surface
//   body_crossing_edges   edges of E touching or crossing the body surface (exact)
//   self_crossing_edges   edges of E touching a cloth triangle that shares no welded vertex with
//                         them (exact), with the pairs of pieces involved (an edge touching more
//                         than kMaxContactsPerEdge triangles counts for the pieces of the first)
//   folds                 neighbour triangles inside a piece whose normals have dot < -0.5
//   theta_in / theta_out  smallest normal dot of neighbour triangles inside pieces / of triangle
//                         pairs that become neighbours by sewing with consistent winding (Eq. 13)
//   strain                stretch of the edges of E: max(0, length / rest length - 1), rest
//                         lengths from rest_positions (compression does not count); the most
//                         stretched edge's distance from the body
//   seam gap              distance between the two vertices of a sewing pair or of a dart pair
//                         (a dart's mouth is a seam too: open, it is a hole in the garment)
//   tightest opening      the garment's opening (a boundary loop after welding) that the body
//                         inside it stretches most: girth of the body inside / rest length − 1
//   misplaced             piece_placement.h, and pieces turned inside out (piece_facing.h)

#include <Eigen/Core>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/core/mesh_topology.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/body_axes.h"
#include "engine/quality/exact_intersections.h"
#include "engine/quality/expected_region.h"
#include "engine/quality/opening_fit.h"
#include "engine/quality/piece_facing.h"
#include "engine/quality/piece_placement.h"

namespace garment {

// Neighbour triangles inside a piece whose normals' dot is below this make a fold.
constexpr double kFoldNormalDot = -0.5;

// A body prepared for checking garments against it; build once and share.
struct BodyReference {
  explicit BodyReference(const BodyMesh& body) : mesh(body), surface(mesh), axes(body_axes(mesh)) {}
  const BodyMesh mesh;  // a copy: callers build references from temporaries
  BodySurfaceQueries surface;
  BodyAxes axes;
};

struct PiecePairCount {
  int piece_a = 0, piece_b = 0;  // piece_a <= piece_b (equal: a piece crossing itself)
  int count = 0;                 // edges of either piece touching a triangle of the other
};

// An opening (opening_fit.h) against the body inside it where it sits.
struct OpeningFit {
  std::vector<int> pieces;  // the pieces it runs along; empty: no opening has body inside it
  double rest_length_m = 0.0;
  double body_girth_m = 0.0;
  bool seam = false;  // a seam ring (opening_fit.h): `pieces` are the side whose length it has
  // How much the body inside forces the opening to stretch on average: girth / rest length − 1.
  double forced_strain() const {
    return rest_length_m > 0.0 ? body_girth_m / rest_length_m - 1.0 : 0.0;
  }
};

struct GarmentMetrics {
  bool body_checked = false;  // false when measured without a body: body and placement stay 0
  int body_inside_vertices = 0;
  double max_inside_depth_m = 0.0;
  int body_crossing_edges = 0;
  std::vector<int> piece_inside_vertices;  // per piece
  std::vector<int> piece_crossing_edges;   // per piece

  int self_crossing_edges = 0;
  std::vector<PiecePairCount> self_crossing_pairs;  // sorted by (piece_a, piece_b)

  int folds = 0;
  std::vector<int> piece_folds;  // per piece
  double theta_in = 1.0;         // 1 when there is no pair to compare
  double theta_out = 1.0;

  double max_strain = 0.0;
  double p99_strain = 0.0;
  std::vector<double> piece_max_strain;  // per piece
  // Distance from the body's surface to the middle of the most stretched edge (-1 without a body):
  // a few millimetres when the cloth is stretched round the body (a band smaller than the body
  // where it sits), more when it is pulled by a seam or a fold.
  double max_strain_body_distance_m = -1.0;
  // The opening whose body inside stretches it most; past the strain threshold it cannot pass
  // where it sits, however the cloth around it is arranged.
  OpeningFit tightest_opening;

  double max_seam_gap_m = 0.0;           // over stitches and dart mouths
  std::vector<double> stitch_max_gap_m;  // per Garment::stitches entry
  std::vector<double> dart_max_gap_m;    // per Garment::darts entry

  std::vector<Misplacement> misplaced;
  std::vector<double> piece_area_facing_body;  // per piece (piece_facing.h); empty without a body

  double seconds_body = 0.0;           // inside vertices and body crossings
  double seconds_self_crossing = 0.0;  // cloth-cloth contacts
  double seconds_total = 0.0;
};

// Where the metrics' counts and maxima come from, per element of one garment state: what the
// studio draws over the garment. Filled by GarmentChecker::measure alongside the metrics, with the
// same definitions (the list at the top of this file), so that a count in the metrics is the
// number of elements flagged here.
struct GarmentDiagnostics {
  // #V: the largest strain of the edges at each vertex (0 at a vertex whose edges are all at or
  // below their rest length).
  Eigen::VectorXd vertex_strain;
  // #V: 1 for a vertex strictly inside the body; empty when measured without a body.
  std::vector<char> vertex_inside_body;
  Eigen::MatrixX2i body_crossing_edges;  // #Eb by 2 vertex ids: edges touching the body surface
  Eigen::MatrixX2i self_crossing_edges;  // #Es by 2 vertex ids: edges touching other cloth
  // #F by 2 vertex ids: for each fold, the edge shared by the two triangles folded onto each other.
  Eigen::MatrixX2i fold_edges;
  Eigen::VectorXd sewing_pair_gap_m;  // per Garment::sewing_pairs row: distance of its two vertices
  Eigen::VectorXd dart_pair_gap_m;    // per Garment::dart_pairs row
};

class GarmentChecker {
 public:
  // `garment` and `body` (may be null: no body metrics, no placement check) must outlive the
  // checker. regions: one per piece (expected_regions_from_names when nothing better is known).
  GarmentChecker(const Garment& garment, const BodyReference* body,
                 std::vector<ExpectedRegion> regions);

  // positions: #V×3 garment state. diagnostics, when given, receives the per-element flags and
  // values the metrics are aggregated from.
  GarmentMetrics measure(const Eigen::MatrixX3d& positions,
                         GarmentDiagnostics* diagnostics = nullptr) const;

  // #V welded vertex ids (sewing and dart pairs joined transitively).
  const Eigen::VectorXi& welded() const { return welded_; }

 private:
  const Garment& garment_;
  const BodyReference* body_;
  std::vector<ExpectedRegion> regions_;
  MeshEdges edges_;  // of the unwelded pieces
  Eigen::VectorXd rest_lengths_;
  Eigen::VectorXi welded_;
  std::vector<Eigen::Vector2i> seam_neighbours_;  // triangle pairs adjacent by sewing only
  std::vector<Opening> openings_;
};

// #V class of each vertex with its seam and dart partners welded (welded_vertices plus the dart
// pairs: a closed dart is a seam too); triangles sharing a class count as adjacent.
Eigen::VectorXi weld_seams_and_darts(const Garment& garment);

// #P: the distance between the two vertices of each row of `pairs` (#P by 2 ids into
// `positions`, #V by 3): the gap of each sewing or dart pair.
Eigen::VectorXd pair_gaps(const Eigen::MatrixX2i& pairs, const Eigen::MatrixX3d& positions);

// One-off measurement (builds a checker).
GarmentMetrics measure_garment(const Garment& garment, const Eigen::MatrixX3d& positions,
                               const BodyReference* body,
                               const std::vector<ExpectedRegion>& regions);

}  // namespace garment
