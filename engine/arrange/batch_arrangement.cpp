#include "engine/arrange/batch_arrangement.h"

#include <algorithm>
#include <chrono>

#include "engine/energy/fixing_potential.h"
#include "engine/energy/objective.h"
#include "engine/energy/self_repulsion_potential.h"
#include "engine/start_shapes/limb_wrap.h"

namespace garment {

const char* to_string(ArrangeStep step) {
  switch (step) {
    case ArrangeStep::Align:
      return "align";
    case ArrangeStep::RemoveBodyIntersections:
      return "remove body intersections";
    case ArrangeStep::Refine:
      return "refine";
  }
  return "?";
}

BatchArrangement::BatchArrangement(ArrangementContext& context, std::vector<int> pieces,
                                   std::vector<bool> arranged)
    : context_(&context),
      pieces_(std::move(pieces)),
      arranged_(std::move(arranged)),
      placed_(arranged_) {
  update_rings();
}

std::vector<bool> BatchArrangement::batch_mask() const {
  std::vector<bool> mask(context_->garment.pieces.size(), false);
  for (int piece : pieces_)
    mask[piece] = true;
  return mask;
}

void BatchArrangement::update_rings() {
  const Garment& garment = context_->garment;
  vertices_ = context_->vertices_of(pieces_);
  is_batch_vertex_.assign(garment.vertex_count(), 0);
  is_arranged_vertex_.assign(garment.vertex_count(), 0);
  for (int v : vertices_)
    is_batch_vertex_[v] = 1;
  for (int v = 0; v < garment.vertex_count(); ++v)
    if (arranged_[garment.vertex_piece(v)]) is_arranged_vertex_[v] = 1;
  // The sewing boundary between the batch and the arranged set, seen from both sides.
  std::vector<int> arranged_boundary, batch_boundary;
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    for (int side = 0; side < 2; ++side) {
      const int own = garment.sewing_pairs(k, side), other = garment.sewing_pairs(k, 1 - side);
      if (is_arranged_vertex_[own] && is_batch_vertex_[other]) arranged_boundary.push_back(own);
      if (is_batch_vertex_[own] && is_arranged_vertex_[other]) batch_boundary.push_back(own);
    }
  }
  const ArrangementParameters& parameters = context_->parameters;
  arranged_ring_ = context_->graph.rings(arranged_boundary, is_arranged_vertex_,
                                         std::max(parameters.refine_rings, parameters.seam_rings));
  batch_ring_ =
      context_->graph.rings(batch_boundary, is_batch_vertex_, context_->garment.vertex_count());
}

void BatchArrangement::place_new_pieces(Eigen::MatrixX3d& positions) {
  const Garment& garment = context_->garment;
  Eigen::MatrixX3d outsides(garment.vertex_count(), 3);
  for (int piece : pieces_) {
    if (placed_[piece]) continue;
    // Aligned to the arranged pieces, which have their shape; batch pieces placed before it (rigid
    // copies, or wrapped round an arm) only guide a piece that has no arranged partner (after
    // growth, or a cuff selected with its sleeve).
    RigidTransform transform = context_->aligner.fit(piece, arranged_, positions);
    const std::vector<bool>* guides = &arranged_;
    if (transform.sewing_pairs < 2) {
      transform = context_->aligner.fit(piece, placed_, positions);
      guides = &placed_;
    }
    context_->aligner.place(piece, transform, positions);
    const Piece& info = garment.pieces[piece];
    outsides.middleRows(info.first_vertex, info.vertex_count).rowwise() =
        transform.rotation.col(2).transpose();
    if (!wrap_round_arm(garment, piece, *guides, context_->landmarks, *context_->body,
                        context_->parameters.limb_wrap, positions, outsides))
      drape_from_seam(garment, piece, arranged_, transform, context_->parameters.seam_drape,
                      context_->landmarks, positions, outsides);
    context_->aligner.lift_out_of_body(piece, outsides, *context_->body,
                                       context_->parameters.energy.body_distance,
                                       context_->parameters.lift_taper, positions);
    placed_[piece] = true;
  }
}

bool BatchArrangement::grow() {
  const Garment& garment = context_->garment;
  const std::vector<bool> in_batch = batch_mask();
  std::vector<bool> added(garment.pieces.size(), false);
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    const int a = garment.vertex_piece(garment.sewing_pairs(k, 0));
    const int b = garment.vertex_piece(garment.sewing_pairs(k, 1));
    for (const auto& [inside, outside] : {std::pair{a, b}, std::pair{b, a}})
      if (in_batch[inside] && !in_batch[outside] && !arranged_[outside]) added[outside] = true;
  }
  bool any = false;
  for (std::size_t p = 0; p < added.size(); ++p) {
    if (!added[p]) continue;
    pieces_.push_back(static_cast<int>(p));
    any = true;
  }
  if (any) update_rings();
  return any;
}

BatchArrangement::Domain BatchArrangement::domain(int rings_free, int rings_fixed_beyond) const {
  const Garment& garment = context_->garment;
  Domain result{ActiveSet(garment.vertex_count(), VertexRole::Outside), {}};
  for (int v = 0; v < garment.vertex_count(); ++v) {
    if (is_batch_vertex_[v]) {
      result.active.set_role(v, VertexRole::Free);
    } else if (is_arranged_vertex_[v]) {
      const int ring = arranged_ring_[v];
      const bool free = ring >= 0 && ring <= rings_free;
      result.active.set_role(v, free ? VertexRole::Free : VertexRole::Fixed);
      if (free && ring > rings_fixed_beyond) result.softly_fixed.push_back(v);
    }
  }
  return result;
}

int BatchArrangement::solve_with(Objective& objective, int iterations, const char* stage,
                                 Eigen::MatrixX3d& positions, Observer* observer,
                                 const IterateCallback& on_iterate, StepRecord& record) {
  if (iterations <= 0 || record.cancelled) return 0;
  SolverSettings settings;
  settings.max_iterations = iterations;
  settings.stage = stage;
  settings.on_iterate = on_iterate;
  const SolveReport report = solve(objective, positions, settings, observer);
  record.iterations += report.iterations;
  record.work += report.work;
  record.final_energy = report.final_energy;
  record.cancelled = report.reason == StopReason::Cancelled;
  return report.iterations;
}

void BatchArrangement::add_self_repulsion(Objective& objective) const {
  // Eq. 12: the batch stays outside the arranged pieces. Vertices on the seam and next to it are
  // held by sewing at the partner's triangles; repelling them would only fight the seam.
  std::vector<int> repelled;
  for (int v : vertices_)
    if (batch_ring_[v] < 0 || batch_ring_[v] > 1) repelled.push_back(v);
  const Garment& garment = context_->garment;
  const int own = context_->piece_garment[pieces_.front()];
  std::vector<int> obstacles;
  for (int t = 0; t < garment.triangle_count(); ++t) {
    const int piece = garment.triangle_piece(t);
    if (arranged_[piece] && context_->piece_garment[piece] == own) obstacles.push_back(t);
  }
  add_repulsion(objective, std::move(repelled), std::move(obstacles));
}

void BatchArrangement::add_outfit_repulsion(Objective& objective, const ActiveSet& active) const {
  const Garment& garment = context_->garment;
  const int own = context_->piece_garment[pieces_.front()];
  if (own == 0) return;
  std::vector<int> repelled, obstacles;
  for (int v = 0; v < garment.vertex_count(); ++v)
    if (active.is_free(v) && context_->piece_garment[garment.vertex_piece(v)] == own)
      repelled.push_back(v);
  for (int t = 0; t < garment.triangle_count(); ++t) {
    const int piece = garment.triangle_piece(t);
    if (arranged_[piece] && context_->piece_garment[piece] < own) obstacles.push_back(t);
  }
  add_repulsion(objective, std::move(repelled), std::move(obstacles));
}

void BatchArrangement::add_repulsion(Objective& objective, std::vector<int> repelled,
                                     std::vector<int> obstacles) const {
  if (obstacles.empty() || repelled.empty()) return;
  const EnergyParameters& energy = context_->parameters.energy;
  SelfRepulsionSettings self;
  self.stiffness = energy.self_repulsion_stiffness;
  self.buffer = energy.repulsion_buffer;
  self.search_radius = energy.self_repulsion_search_radius;
  self.refresh_interval = energy.self_repulsion_refresh_interval;
  objective.add(std::make_shared<SelfRepulsionPotential>(
      context_->garment.triangles, std::move(repelled), std::move(obstacles), self));
}

StepRecord BatchArrangement::run(ArrangeStep step, int visit, Eigen::MatrixX3d& positions,
                                 Observer* observer, const IterateCallback& on_iterate) {
  const auto start = std::chrono::steady_clock::now();
  const ArrangementParameters& parameters = context_->parameters;
  const EnergyParameters& energy = parameters.energy;
  StepRecord record;
  record.step = step;
  record.visit = visit;
  place_new_pieces(positions);
  const auto finish = [&] {
    record.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return record;
  };
  // The phasing ablation: everything happens in the align step.
  if (!parameters.phased && step != ArrangeStep::Align) return finish();

  // Align and body removal: the batch and the seam neighbourhood, arranged vertices held by F^ext.
  const bool widened = step == ArrangeStep::Refine || !parameters.phased;
  Domain domain_now = widened ? domain(parameters.refine_rings, parameters.seam_rings)
                              : domain(parameters.seam_rings, -1);
  Eigen::MatrixX3d targets(domain_now.softly_fixed.size(), 3);
  for (std::size_t i = 0; i < domain_now.softly_fixed.size(); ++i)
    targets.row(i) = positions.row(domain_now.softly_fixed[i]);
  auto fixing =
      std::make_shared<FixingPotential>(domain_now.softly_fixed, targets, energy.fixing_stiffness);
  context_->bending->set_stiffness(energy.bending_stiffness *
                                   (widened ? 1.0 : energy.alignment_bending_factor));

  Objective objective(domain_now.active);
  objective.add(context_->stretch).add(context_->bending).add(context_->sewing).add(fixing);
  objective.add(context_->body_repulsion);
  add_outfit_repulsion(objective, domain_now.active);
  const int deepest = *std::max_element(batch_ring_.begin(), batch_ring_.end());
  const int body_rounds = deepest < 0 ? 0 : deepest / parameters.rings_per_round + 1;

  if (!parameters.phased) {
    add_self_repulsion(objective);
    context_->gravity->set_acceleration(energy.gravity * energy.mild_gravity_factor);
    objective.add(context_->gravity);
    const int iterations =
        parameters.align.iterations(visit) + body_rounds * parameters.body_round.iterations(visit) +
        parameters.body_final.iterations(visit) + parameters.refine.iterations(visit) +
        parameters.settle.iterations(visit);
    solve_with(objective, iterations, "all potentials at once", positions, observer, on_iterate,
               record);
    return finish();
  }

  switch (step) {
    case ArrangeStep::Align: {
      // Body repulsion only where the piece starts outside the body: what is inside would be pushed
      // to whichever side is nearer, often the wrong one (§7.2, Fig. 8d).
      ActiveSet active = domain_now.active;
      for (int v : vertices_)
        active.set_body_repulsion(v, context_->body->value(positions.row(v).transpose()) > 0.0);
      objective.set_active_set(active);
      solve_with(objective, parameters.align.iterations(visit), "align", positions, observer,
                 on_iterate, record);
      break;
    }
    case ArrangeStep::RemoveBodyIntersections: {
      // §7.2: sewing boundary vertices are already outside the body; the rest of the batch follows
      // ring by ring, like a garment being put on.
      ActiveSet active = domain_now.active;
      for (int round = 0; round < body_rounds && !record.cancelled; ++round) {
        const int reach = round * parameters.rings_per_round;
        for (int v : vertices_)
          active.set_body_repulsion(v, batch_ring_[v] >= 0 && batch_ring_[v] <= reach);
        objective.set_active_set(active);
        solve_with(objective, parameters.body_round.iterations(visit), "remove body intersections",
                   positions, observer, on_iterate, record);
      }
      objective.set_active_set(domain_now.active);  // everything on, unreached pieces included
      solve_with(objective, parameters.body_final.iterations(visit), "remove body intersections",
                 positions, observer, on_iterate, record);
      break;
    }
    case ArrangeStep::Refine: {
      add_self_repulsion(objective);
      solve_with(objective, parameters.refine.iterations(visit), "refine", positions, observer,
                 on_iterate, record);
      context_->gravity->set_acceleration(energy.gravity * energy.mild_gravity_factor);
      objective.add(context_->gravity);
      solve_with(objective, parameters.settle.iterations(visit), "refine", positions, observer,
                 on_iterate, record);
      break;
    }
  }
  return finish();
}

}  // namespace garment
