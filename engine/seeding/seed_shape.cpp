#include "engine/seeding/seed_shape.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>

#include "engine/core/error.h"
#include "engine/energy/bending_potential.h"
#include "engine/energy/body_distance_potential.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/centring_potential.h"
#include "engine/energy/objective.h"
#include "engine/energy/sewing_potential.h"
#include "engine/energy/stretch_potential.h"
#include "engine/energy/upward_potential.h"
#include "engine/solver/chebyshev_solver.h"

namespace garment {
namespace {

struct RestBox {
  Eigen::Vector2d lower, upper;
  Eigen::Vector2d centre() const { return 0.5 * (lower + upper); }
  Eigen::Vector2d size() const { return upper - lower; }
};

RestBox rest_box(const Garment& garment, int piece) {
  const Piece& info = garment.pieces[piece];
  const auto rows = garment.rest_positions.middleRows(info.first_vertex, info.vertex_count);
  return {rows.colwise().minCoeff().transpose(), rows.colwise().maxCoeff().transpose()};
}

// Where each piece of a part sits in a common 2D layout (arc length across, height up): pieces sewn
// side to side follow each other left to right with their seams matched, as they will be worn.
struct PartLayout {
  std::vector<int> pieces;
  std::vector<Eigen::Vector2d> offsets;  // added to each piece's rest positions
  RestBox box;                           // of the laid-out part
  // When the pieces sewn side to side close into a ring (a waistband in a front and a back): the
  // ring's length in the layout, from the first piece's left seam around to the same seam.
  double ring_length = 0.0;
};

// The side seam joining the right side of `from` to the left side of `to`, as the midpoints of
// the seam on each piece (rest frames): a seam more vertical than horizontal, right of the centre
// of `from` and left of the centre of `to`; else nothing. Two pieces may be sewn at both sides (a
// waistband's front and back): each stitch is looked at.
bool side_seam(const Garment& garment, int from, int to, Eigen::Vector2d& on_from,
               Eigen::Vector2d& on_to) {
  const double from_centre = rest_box(garment, from).centre().x();
  const double to_centre = rest_box(garment, to).centre().x();
  for (const StitchPairs& range : garment.stitches) {
    if (range.pair_count < 2) continue;
    const int a = garment.sewing_pairs(range.first_pair, 0),
              b = garment.sewing_pairs(range.first_pair, 1);
    int first = range.first_pair, last = range.first_pair + range.pair_count - 1;
    int column = -1;
    if (garment.vertex_piece(a) == from && garment.vertex_piece(b) == to) column = 0;
    if (garment.vertex_piece(b) == from && garment.vertex_piece(a) == to) column = 1;
    if (column < 0) continue;
    const Eigen::Vector2d from_start =
        garment.rest_positions.row(garment.sewing_pairs(first, column));
    const Eigen::Vector2d from_end = garment.rest_positions.row(garment.sewing_pairs(last, column));
    const Eigen::Vector2d to_start =
        garment.rest_positions.row(garment.sewing_pairs(first, 1 - column));
    const Eigen::Vector2d to_end =
        garment.rest_positions.row(garment.sewing_pairs(last, 1 - column));
    const Eigen::Vector2d direction = from_end - from_start;
    if (std::abs(direction.y()) < std::abs(direction.x())) continue;
    const Eigen::Vector2d from_middle = 0.5 * (from_start + from_end);
    const Eigen::Vector2d to_middle = 0.5 * (to_start + to_end);
    if (from_middle.x() <= from_centre || to_middle.x() >= to_centre) continue;
    on_from = from_middle;
    on_to = to_middle;
    return true;
  }
  return false;
}

PartLayout lay_out_part(const Garment& garment, const std::vector<int>& pieces) {
  PartLayout layout;
  std::map<int, int> right_of;  // piece → the piece sewn to its right end
  std::map<int, std::pair<Eigen::Vector2d, Eigen::Vector2d>> right_seam;
  for (int a : pieces) {
    for (int b : pieces) {
      Eigen::Vector2d on_a, on_b;
      if (a == b || right_of.count(a) || !side_seam(garment, a, b, on_a, on_b)) continue;
      right_of[a] = b;
      right_seam[a] = {on_a, on_b};
    }
  }
  std::vector<bool> has_left(garment.pieces.size(), false);
  for (const auto& [a, b] : right_of)
    has_left[b] = true;
  std::vector<bool> laid(garment.pieces.size(), false);
  Eigen::Vector2d next_free(0.0, 0.0);
  // Open chains first (from their left end), then cycles, then pieces sewn to none of the others.
  std::vector<int> starts;
  for (int piece : pieces)
    if (!has_left[piece]) starts.push_back(piece);
  for (int piece : pieces)
    starts.push_back(piece);
  for (int start : starts) {
    if (laid[start]) continue;
    const RestBox box = rest_box(garment, start);
    const Eigen::Vector2d start_offset(next_free.x() - box.lower.x(), -box.centre().y());
    Eigen::Vector2d offset = start_offset;
    std::size_t chain_length = 0;
    for (int piece = start; piece >= 0 && !laid[piece];) {
      laid[piece] = true;
      layout.pieces.push_back(piece);
      layout.offsets.push_back(offset);
      ++chain_length;
      next_free.x() = std::max(next_free.x(), offset.x() + rest_box(garment, piece).upper.x());
      const auto right = right_of.find(piece);
      if (right == right_of.end()) break;
      const auto& [on_piece, on_next] = right_seam[piece];
      offset = offset + on_piece - on_next;  // the seam midpoints coincide
      piece = right->second;
      // Back at the start: the whole part is one closed ring.
      if (piece == start && chain_length == pieces.size())
        layout.ring_length = offset.x() - start_offset.x();
    }
  }
  layout.box = {Eigen::Vector2d::Constant(1e30), Eigen::Vector2d::Constant(-1e30)};
  for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
    const RestBox box = rest_box(garment, layout.pieces[i]);
    layout.box.lower = layout.box.lower.cwiseMin(box.lower + layout.offsets[i]);
    layout.box.upper = layout.box.upper.cwiseMax(box.upper + layout.offsets[i]);
  }
  return layout;
}

// How much a piece's sewn neighbours outside its part say "front" (> 0) or "back" (< 0).
double front_score(const Scene& scene, int piece, const std::vector<int>& part) {
  const Garment& garment = *scene.garment;
  const PieceClassification& classification = scene.classification;
  double score = 0.0;
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    for (int side = 0; side < 2; ++side) {
      if (garment.vertex_piece(garment.sewing_pairs(k, side)) != piece) continue;
      const int other = garment.vertex_piece(garment.sewing_pairs(k, 1 - side));
      if (std::find(part.begin(), part.end(), other) != part.end()) continue;
      const int group = classification.piece_group[other];
      score += classification.probability(group, SeedClass::FrontChest) +
               classification.probability(group, SeedClass::FrontPelvis) -
               classification.probability(group, SeedClass::BackChest) -
               classification.probability(group, SeedClass::BackPelvis);
    }
  }
  return score;
}

}  // namespace

void place_seed_on_surfaces(const Scene& scene, const SeedPlan& plan, double distance,
                            Eigen::MatrixX3d& positions) {
  const Garment& garment = *scene.garment;
  for (const SeedPart& part : plan.parts) {
    const BodyLocation* location = &scene.body->location(part.location);
    const PartLayout layout = lay_out_part(garment, part.pieces);
    const Eigen::Vector3d axis = location->axis.normalized();
    if (location->surface == LocationSurface::cylinder) {
      // Around the axis: the layout's arc runs along up × outward, which at the front is the body's
      // left (+x), so every piece's outside (+z of its rest frame) faces away from the axis.
      Eigen::Vector3d front = Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(axis) * axis;
      front.normalize();
      const Eigen::Vector3d across = axis.cross(front);
      const double span = layout.box.size().x();
      // A closed ring goes all the way round, so that every seam of it starts closed: when it is
      // shorter than the cylinder (a waistband cut to the waist goes round the cylinder that
      // encloses the waist's section), it starts stretched and tightens onto the body; left with
      // a gap, the seam across the gap would pull the ring's ends through the body and twist it.
      const bool ring = layout.ring_length > 0.0;
      const double radius = std::max(
          location->radius + distance,
          (ring ? 1.0 : 1.02) * (ring ? layout.ring_length : span) / (2.0 * std::numbers::pi));
      const double arc_scale =
          ring ? 2.0 * std::numbers::pi * radius / layout.ring_length : 1.0;  // stretch ≥ 1
      // The piece sewn to the front of the garment faces the front; else the middle of the part
      // does.
      double front_arc = layout.box.centre().x();
      double best = 0.0;
      for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
        const double score = front_score(scene, layout.pieces[i], part.pieces);
        if (score > best) {
          best = score;
          front_arc = rest_box(garment, layout.pieces[i]).centre().x() + layout.offsets[i].x();
        }
      }
      for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
        const Piece& piece = garment.pieces[layout.pieces[i]];
        for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
          const Eigen::Vector2d laid =
              garment.rest_positions.row(v).transpose() + layout.offsets[i];
          const double angle = arc_scale * (laid.x() - front_arc) / radius;
          positions.row(v) = (location->center + (laid.y() - layout.box.centre().y()) * axis +
                              radius * (std::cos(angle) * front + std::sin(angle) * across))
                                 .transpose();
        }
      }
    } else {
      // On the plane, `distance` in front of it, upright: rest y along the location's up, rest x
      // along up × normal, so the outside faces along the normal.
      const Eigen::Vector3d up = location->up.normalized();
      const Eigen::Vector3d across = up.cross(axis);
      for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
        const Piece& piece = garment.pieces[layout.pieces[i]];
        for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
          const Eigen::Vector2d laid =
              garment.rest_positions.row(v).transpose() + layout.offsets[i] - layout.box.centre();
          positions.row(v) =
              (location->center + distance * axis + laid.x() * across + laid.y() * up).transpose();
        }
      }
    }
  }
}

SeedShapeReport shape_seed(const Scene& scene, const SeedPlan& plan, const EnergyParameters& energy,
                           Eigen::MatrixX3d& positions, Observer* observer,
                           const std::function<void(const Eigen::MatrixX3d&)>& on_iterate,
                           const SeedShapeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Garment& garment = *scene.garment;
  place_seed_on_surfaces(scene, plan, energy.body_distance, positions);

  ActiveSet active(garment.vertex_count(), VertexRole::Outside);
  std::vector<int> seed_vertices;
  for (int piece : plan.pieces()) {
    const Piece& info = garment.pieces[piece];
    for (int v = info.first_vertex; v < info.first_vertex + info.vertex_count; ++v)
      seed_vertices.push_back(v);
  }
  active.set_role(seed_vertices, VertexRole::Free);
  Objective objective(active);
  std::vector<BendingStencil> stencils = interior_bending_stencils(garment);
  const std::vector<BendingStencil> seam = seam_bending_stencils(garment);
  stencils.insert(stencils.end(), seam.begin(), seam.end());
  objective
      .add(std::make_shared<StretchPotential>(garment, energy.stretch_stiffness,
                                              energy.dart_stiffness,
                                              energy.stretch_compression_factor))
      .add(std::make_shared<BendingPotential>(std::move(stencils),
                                              energy.bending_stiffness * options.bending_factor))
      .add(std::make_shared<SewingPotential>(garment.sewing_pairs, energy.sewing_stiffness))
      .add(std::make_shared<UpwardPotential>(garment, seed_vertices, energy.upward_stiffness))
      .add(std::make_shared<BodyDistancePotential>(scene.sdf, garment.triangles, seed_vertices,
                                                   energy.body_distance_stiffness,
                                                   energy.body_distance))
      .add(std::make_shared<BodyRepulsionPotential>(scene.sdf, energy.body_repulsion_stiffness,
                                                    energy.repulsion_buffer));
  for (const SeedPart& part : plan.parts) {
    const BodyLocation* location = &scene.body->location(part.location);
    std::vector<int> vertices;
    for (int piece : part.pieces) {
      const Piece& info = garment.pieces[piece];
      for (int v = info.first_vertex; v < info.first_vertex + info.vertex_count; ++v)
        vertices.push_back(v);
    }
    // A cylinder's centre is on its axis, where a wrapped part's centre is; a plane's is on the
    // body surface, which the part faces from the cloth-body distance D.
    const Eigen::Vector3d target =
        location->surface == LocationSurface::cylinder
            ? location->center
            : Eigen::Vector3d(location->center +
                              energy.body_distance * location->axis.normalized());
    objective.add(std::make_shared<CentringPotential>(vertices, target, energy.centring_stiffness));
  }
  SolverSettings settings;
  settings.max_iterations = options.iterations;
  settings.stage = "seed";
  settings.on_iterate = on_iterate;
  const SolveReport solved = solve(objective, positions, settings, observer);
  SeedShapeReport report;
  report.iterations = solved.iterations;
  report.final_energy = solved.final_energy;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace garment
