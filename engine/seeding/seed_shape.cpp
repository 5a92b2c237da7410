#include "engine/seeding/seed_shape.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "engine/core/error.h"
#include "engine/core/mesh_topology.h"
#include "engine/energy/bending_potential.h"
#include "engine/energy/body_distance_potential.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/centring_potential.h"
#include "engine/energy/objective.h"
#include "engine/energy/self_repulsion_potential.h"
#include "engine/energy/sewing_potential.h"
#include "engine/energy/stretch_potential.h"
#include "engine/energy/upward_potential.h"
#include "engine/quality/expected_region.h"
#include "engine/seeding/seed_layout.h"
#include "engine/solver/chebyshev_solver.h"

namespace garment {
namespace {

// How much a piece's sewn neighbours outside its part say "front" (> 0) or "back" (< 0).
// The largest stretch (length / rest length − 1) of the springs (mesh edges) of the masked pieces,
// 0 when none stretches: the termination check's strain (termination/termination.h) for one batch.
double max_strain_of(const Garment& garment, const Eigen::MatrixX2i& springs,
                     const std::vector<bool>& pieces, const Eigen::MatrixX3d& positions) {
  double strain = 0.0;
  for (Eigen::Index e = 0; e < springs.rows(); ++e) {
    const int a = springs(e, 0), b = springs(e, 1);
    const double rest = (garment.rest_positions.row(a) - garment.rest_positions.row(b)).norm();
    if (!pieces[garment.vertex_piece(a)] || rest <= 0.0) continue;
    const double length = (positions.row(a) - positions.row(b)).norm();
    strain = std::max(strain, (length - rest) / rest);
  }
  return strain;
}

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

// +1 for a piece named for the front, −1 for the back, 0 otherwise (expected_region.h).
double named_front_score(const Garment& garment, int piece) {
  switch (expected_region_from_name(garment.pieces[piece].name).front_back) {
    case FrontBack::Front:
      return 1.0;
    case FrontBack::Back:
      return -1.0;
    case FrontBack::Any:
      return 0.0;
  }
  return 0.0;
}

// An ellipse x(θ) = a sinθ · across + b cosθ · normal around a torso, walked by arc length: front
// and back chest parts wrap round it so that their side seams start next to each other, under
// the arms, instead of a torso's depth apart on two planes (their seams would then pull the
// armpit corners through the arms).
class EllipseArc {
 public:
  EllipseArc(double a, double b) : a_(a), b_(b) {
    angle_.resize(kSteps + 1);
    length_.resize(kSteps + 1);
    for (int i = 0; i <= kSteps; ++i) {
      angle_[i] = std::numbers::pi * i / kSteps;  // one half; the other mirrors it
      length_[i] = i == 0 ? 0.0 : length_[i - 1] + (point(angle_[i]) - point(angle_[i - 1])).norm();
    }
  }
  double perimeter() const { return 2.0 * length_.back(); }
  // The angle reached after walking `arc` from θ = 0 (negative: the other way), |arc| ≤ half the
  // perimeter.
  double angle_at(double arc) const {
    const double walked = std::min(std::abs(arc), length_.back());
    const auto after = std::lower_bound(length_.begin(), length_.end(), walked);
    const std::size_t i = std::clamp<std::size_t>(after - length_.begin(), 1, kSteps);
    const double t = (walked - length_[i - 1]) / std::max(1e-12, length_[i] - length_[i - 1]);
    return std::copysign(angle_[i - 1] + t * (angle_[i] - angle_[i - 1]), arc);
  }
  // (across, normal) coordinates of the point at angle θ.
  Eigen::Vector2d point(double angle) const { return {a_ * std::sin(angle), b_ * std::cos(angle)}; }

 private:
  static constexpr int kSteps = 720;
  double a_, b_;
  std::vector<double> angle_, length_;
};

// How far under the body's armpits the side seams of a wrapped bodice start at most.
constexpr double kUnderArmpit = 0.02;

// Where a laid-out part's side seams to the opposite part are, from the seams that run up the
// pattern, each taken at the mean of its vertices on this part (layout coordinates): the leftmost
// and rightmost across, and their mean height. Empty without one on each side.
struct SideSeams {
  double left = 0.0, right = 0.0, height = 0.0;
  double top = -std::numeric_limits<double>::infinity();  // highest seam vertex
};

std::optional<SideSeams> side_seams(const Garment& garment, const PartLayout& layout,
                                    const std::vector<int>& opposite_pieces) {
  const auto offset_of = [&](int piece) -> const Eigen::Vector2d* {
    for (std::size_t i = 0; i < layout.pieces.size(); ++i)
      if (layout.pieces[i] == piece) return &layout.offsets[i];
    return nullptr;
  };
  SideSeams seams{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                  0.0};
  int count = 0;
  for (const StitchPairs& stitch : garment.stitches) {
    if (stitch.pair_count < 2) continue;
    for (int side = 0; side < 2; ++side) {
      const int first = garment.sewing_pairs(stitch.first_pair, side);
      const int other = garment.sewing_pairs(stitch.first_pair, 1 - side);
      const Eigen::Vector2d* offset = offset_of(garment.vertex_piece(first));
      if (!offset || std::find(opposite_pieces.begin(), opposite_pieces.end(),
                               garment.vertex_piece(other)) == opposite_pieces.end())
        continue;
      const int last = garment.sewing_pairs(stitch.first_pair + stitch.pair_count - 1, side);
      const Eigen::Vector2d run =
          garment.rest_positions.row(last) - garment.rest_positions.row(first);
      if (std::abs(run.y()) < std::abs(run.x())) continue;  // a shoulder seam
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      for (int k = stitch.first_pair; k < stitch.first_pair + stitch.pair_count; ++k) {
        const Eigen::Vector2d laid =
            garment.rest_positions.row(garment.sewing_pairs(k, side)).transpose() + *offset;
        mean += laid;
        seams.top = std::max(seams.top, laid.y());
      }
      mean /= stitch.pair_count;
      seams.left = std::min(seams.left, mean.x());
      seams.right = std::max(seams.right, mean.x());
      seams.height += mean.y();
      ++count;
    }
  }
  if (count < 2 || !(seams.right > seams.left)) return std::nullopt;
  seams.height /= count;
  return seams;
}

// The mean of a laid-out part's vertices (layout coordinates): the centring potential pulls it to
// the location's centre.
Eigen::Vector2d vertex_mean(const Garment& garment, const PartLayout& layout) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int count = 0;
  for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
    const Piece& piece = garment.pieces[layout.pieces[i]];
    sum += garment.rest_positions.middleRows(piece.first_vertex, piece.vertex_count)
               .colwise()
               .sum()
               .transpose() +
           piece.vertex_count * layout.offsets[i];
    count += piece.vertex_count;
  }
  return sum / std::max(1, count);
}
// The part on the opposite plane (front ↔ back), sewn to this one, or nullptr.
const SeedPart* opposite_part(const Scene& scene, const SeedPlan& plan, const SeedPart& part) {
  const BodyLocation& location = scene.body->location(part.location);
  for (const SeedPart& other : plan.parts) {
    if (&other == &part) continue;
    const BodyLocation& candidate = scene.body->location(other.location);
    if (candidate.surface != LocationSurface::plane ||
        candidate.axis.normalized().dot(location.axis.normalized()) > -0.9)
      continue;
    for (Eigen::Index k = 0; k < scene.garment->sewing_pairs.rows(); ++k) {
      const int a = scene.garment->vertex_piece(scene.garment->sewing_pairs(k, 0));
      const int b = scene.garment->vertex_piece(scene.garment->sewing_pairs(k, 1));
      const auto in = [](const std::vector<int>& pieces, int piece) {
        return std::find(pieces.begin(), pieces.end(), piece) != pieces.end();
      };
      if ((in(part.pieces, a) && in(other.pieces, b)) ||
          (in(part.pieces, b) && in(other.pieces, a)))
        return &other;
    }
  }
  return nullptr;
}
}  // namespace

void place_seed_on_surfaces(const Scene& scene, const SeedPlan& plan, double distance,
                            Eigen::MatrixX3d& positions, SeedStart start) {
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
      // The front is the mean direction of the pieces round the axis, each weighted by how much
      // its sewn neighbours say "front" (back pieces push it away): the seam between the two
      // front pieces of a four-piece collar faces the front, not one of them. Without such
      // neighbours, the middle of the part does. A part whose own pieces are named for their
      // sides is believed over the neighbours, as the seed choice believes names over the
      // classifier (seed_choice.cpp): a many-panel skirt's unnamed panels, which the classifier
      // takes for front and back alike, turned wb_front and wb_back of its waistband round.
      std::vector<double> named_scores;
      for (int piece : layout.pieces)
        named_scores.push_back(named_front_score(garment, piece));
      const bool named = std::any_of(named_scores.begin(), named_scores.end(),
                                     [](double score) { return score != 0.0; });
      double front_arc = layout.box.centre().x();
      Eigen::Vector2d resultant = Eigen::Vector2d::Zero();
      double total_score = 0.0;
      for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
        const double score =
            named ? named_scores[i] : front_score(scene, layout.pieces[i], part.pieces);
        const double arc = rest_box(garment, layout.pieces[i]).centre().x() + layout.offsets[i].x();
        const double angle = arc_scale * arc / radius;
        resultant += score * Eigen::Vector2d(std::cos(angle), std::sin(angle));
        total_score += std::abs(score);
      }
      if (resultant.norm() > 1e-3 * total_score && total_score > 0.0)
        front_arc = std::atan2(resultant.y(), resultant.x()) * radius / arc_scale;
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
      // The part's centre (the mean of its vertices, which the centring potential pulls to the
      // location) starts on the location's centre: a bodice narrowing to its shoulder straps has it
      // well below the middle of its bounding box.
      const Eigen::Vector3d up = location->up.normalized();
      const Eigen::Vector3d across = up.cross(axis);
      const Eigen::Vector2d centre = vertex_mean(garment, layout);
      const SeedPart* opposite =
          start == SeedStart::Flat ? nullptr : opposite_part(scene, plan, part);
      if (!opposite) {
        for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
          const Piece& piece = garment.pieces[layout.pieces[i]];
          for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
            const Eigen::Vector2d laid =
                garment.rest_positions.row(v).transpose() + layout.offsets[i] - centre;
            positions.row(v) =
                (location->center + distance * axis + laid.x() * across + laid.y() * up)
                    .transpose();
          }
        }
        continue;
      }
      // Front and back sewn together: both wrap round one ellipse through the two planes' centres,
      // as wide as the torso, each centred between its side seams so that these meet at the sides.
      // A garment wider than the ellipse deepens it (ease in front and behind, not under the
      // arms); a narrower one starts stretched round it, as a ring does.
      const BodyLocation& other = scene.body->location(opposite->location);
      const double half_gap = 0.5 * (location->center - other.center).dot(axis);
      const Eigen::Vector3d ellipse_centre = location->center - half_gap * axis;
      const double half_width = std::max(location->half_width, other.half_width) + distance;
      const PartLayout opposite_layout = lay_out_part(garment, opposite->pieces);
      double garment_round = layout.box.size().x() + opposite_layout.box.size().x();
      double middle = centre.x(), lift = 0.0;
      const std::optional<SideSeams> seams = side_seams(garment, layout, opposite->pieces);
      const std::optional<SideSeams> opposite_seams =
          side_seams(garment, opposite_layout, part.pieces);
      if (seams && opposite_seams) {
        garment_round =
            (seams->right - seams->left) + (opposite_seams->right - opposite_seams->left);
        middle = 0.5 * (seams->left + seams->right);
        // Both parts' side seams at the same height: halfway between where each part's centring
        // alone would put them.
        const double here = location->center.dot(up) - centre.y();
        const double there = other.center.dot(up) - vertex_mean(garment, opposite_layout).y();
        lift = 0.5 * ((there + opposite_seams->height) - (here + seams->height));
        if (start == SeedStart::WrappedUnderArmpits) {
          const double highest =
              std::max(here + seams->top + lift, there + opposite_seams->top - lift);
          const double armpits = scene.body->landmarks.armpits - kUnderArmpit;
          if (highest > armpits) lift -= highest - armpits;
        }
      }
      double half_depth = half_gap + distance;
      for (int i = 0; i < 100 && EllipseArc(half_width, half_depth).perimeter() < garment_round;
           ++i)
        half_depth *= 1.02;
      const EllipseArc ellipse(half_width, half_depth);
      const double arc_scale = std::max(1.0, ellipse.perimeter() / garment_round);
      for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
        const Piece& piece = garment.pieces[layout.pieces[i]];
        for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
          const Eigen::Vector2d laid =
              garment.rest_positions.row(v).transpose() + layout.offsets[i] - centre;
          const double arc = arc_scale * (laid.x() + centre.x() - middle);
          const Eigen::Vector2d round = ellipse.point(ellipse.angle_at(arc));
          positions.row(v) =
              (ellipse_centre + round.x() * across + round.y() * axis + (laid.y() + lift) * up)
                  .transpose();
        }
      }
    }
  }
}

namespace {

SolveReport solve_seed_shape(const Scene& scene, const SeedPlan& plan,
                             const EnergyParameters& energy, Eigen::MatrixX3d& positions,
                             Observer* observer,
                             const std::function<void(const Eigen::MatrixX3d&)>& on_iterate,
                             const SeedShapeOptions& options) {
  const Garment& garment = *scene.garment;
  ActiveSet active(garment.vertex_count(), VertexRole::Outside);
  // The body distance draws a piece to the body below the crotch only if the piece is named for
  // a side of the body (a trouser leg: a leg is there to draw it to). Drawn there, a skirt's
  // front and back met in the gap between the legs and crossed (gc_0109: 42 edge-triangle
  // contacts between its seed pieces 25 to 33 cm below the crotch; none now); trousers left
  // undrawn there pressed their legs through the body (pants__pants_straight_sides). Of the 55
  // GarmentCode patterns seeded at the pelvis (skirts and trousers), 46 → 48 clean.
  std::vector<int> seed_vertices, attracted;
  for (int piece : plan.pieces()) {
    const Piece& info = garment.pieces[piece];
    const bool leg = expected_region_from_name(info.name).left_right != LeftRight::Any;
    for (int v = info.first_vertex; v < info.first_vertex + info.vertex_count; ++v) {
      seed_vertices.push_back(v);
      if (leg || positions(v, 1) >= scene.body->landmarks.crotch) attracted.push_back(v);
    }
  }
  // The garments underneath are held where they are: a contact with a corner Outside the solve
  // would take no part in it. (Letting them give way near the seed, held by a soft spring, so that
  // a waistband would press a shirt to the body: no outfit of the tuning half's 40 pairs changed.)
  for (int t : options.obstacle_triangles)
    for (int corner = 0; corner < 3; ++corner)
      active.set_role(garment.triangles(t, corner), VertexRole::Fixed);
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
      .add(std::make_shared<BodyDistancePotential>(scene.sdf, garment.triangles, attracted,
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
  if (!options.obstacle_triangles.empty()) {
    SelfRepulsionSettings self;
    self.stiffness = energy.self_repulsion_stiffness;
    self.buffer = energy.repulsion_buffer;
    self.search_radius = options.obstacle_search_radius;
    self.refresh_interval = energy.self_repulsion_refresh_interval;
    objective.add(std::make_shared<SelfRepulsionPotential>(garment.triangles, seed_vertices,
                                                           options.obstacle_triangles, self));
  }
  SolverSettings settings;
  settings.max_iterations = options.iterations;
  settings.stage = "seed";
  settings.on_iterate = on_iterate;
  return solve(objective, positions, settings, observer);
}

}  // namespace

SeedShapeReport shape_seed(const Scene& scene, const SeedPlan& plan, const EnergyParameters& energy,
                           Eigen::MatrixX3d& positions, Observer* observer,
                           const std::function<void(const Eigen::MatrixX3d&)>& on_iterate,
                           const SeedShapeOptions& options) {
  const auto clock_start = std::chrono::steady_clock::now();
  const Garment& garment = *scene.garment;
  // A front and back wrapped round the torso can start with the corner under an armhole inside the
  // arm, pushed out in front of it by the solve: that piece ends stretched round the arm (200 % and
  // more), which no later phase undoes. Such a seed is shaped again from the next start, with the
  // side seams under the armpits, then flat; the first unbroken shape, or the least stretched, is
  // kept. (Lowering every bodice would move the ones that fit off their chest location.)
  std::vector<bool> seed_mask(garment.pieces.size(), false);
  for (int piece : plan.pieces())
    seed_mask[piece] = true;
  const Eigen::MatrixX2i springs =
      build_mesh_edges(garment.triangles, garment.vertex_count()).edges;
  const Eigen::MatrixX3d unshaped = positions;
  SeedShapeReport report;
  report.attempts = 0;
  report.max_strain = std::numeric_limits<double>::infinity();
  int iterations = 0;
  // Without a front and back sewn together every start is the same.
  const bool wrapped_pair = std::any_of(
      plan.parts.begin(), plan.parts.end(),
      [&](const SeedPart& part) { return opposite_part(scene, plan, part) != nullptr; });
  for (SeedStart start : {SeedStart::Wrapped, SeedStart::WrappedUnderArmpits, SeedStart::Flat}) {
    Eigen::MatrixX3d shaped = unshaped;
    place_seed_on_surfaces(scene, plan, energy.body_distance, shaped, start);
    const SolveReport solved =
        solve_seed_shape(scene, plan, energy, shaped, observer, on_iterate, options);
    iterations += solved.iterations;
    report.work += solved.work;
    ++report.attempts;
    const double strain = max_strain_of(garment, springs, seed_mask, shaped);
    if (strain < report.max_strain) {
      positions = shaped;
      report.max_strain = strain;
      report.final_energy = solved.final_energy;
    }
    if (!wrapped_pair || report.max_strain <= options.broken_strain) break;
  }
  report.iterations = iterations;
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return report;
}

}  // namespace garment
