#include "engine/energy/objective.h"

#include <algorithm>
#include <stdexcept>

namespace garment {

Objective& Objective::add(std::shared_ptr<Potential> potential) {
  if (!potential) throw std::invalid_argument("Objective::add: null potential");
  potentials_.push_back(std::move(potential));
  assembler_stale_ = true;
  return *this;
}

void Objective::remove(const Potential& potential) {
  const auto it = std::find_if(potentials_.begin(), potentials_.end(),
                               [&](const auto& p) { return p.get() == &potential; });
  if (it == potentials_.end()) return;
  potentials_.erase(it);
  assembler_stale_ = true;
}

void Objective::set_active_set(ActiveSet active) {
  active_ = std::move(active);
  assembler_stale_ = true;
}

Assembler& Objective::assembler_for(const Positions& x) {
  if (x.rows() != active_.vertex_count())
    throw std::invalid_argument("Objective: positions have " + std::to_string(x.rows()) +
                                " rows, the active set " + std::to_string(active_.vertex_count()) +
                                " vertices");
  for (const auto& potential : potentials_) {
    if (potential->is_bound_to(active_)) continue;
    potential->bind(active_);
    assembler_stale_ = true;
  }
  if (assembler_stale_) {
    std::vector<Potential*> raw;
    raw.reserve(potentials_.size());
    for (const auto& potential : potentials_)
      raw.push_back(potential.get());
    assembler_.prepare(raw, active_, x);
    assembler_stale_ = false;
  }
  return assembler_;
}

double Objective::evaluate(const Eigen::MatrixX3d& x, Eigen::MatrixX3d* gradient,
                           Eigen::MatrixX3d* hessian_diagonal, int iteration) {
  const Positions positions = to_positions(x);
  Assembler& assembler = assembler_for(positions);
  const double energy = assembler.accumulate(positions, iteration, true);
  if (gradient) gradient->setZero(x.rows(), 3);
  if (hessian_diagonal) hessian_diagonal->setZero(x.rows(), 3);
  assembler.gather(positions, [&](int vertex, const Eigen::Vector3d& g, const Eigen::Vector3d& d) {
    if (gradient) gradient->row(vertex) = g.transpose();
    if (hessian_diagonal) hessian_diagonal->row(vertex) = d.transpose();
    return 0.0;
  });
  return energy;
}

std::vector<PotentialEnergy> Objective::energies(const Eigen::MatrixX3d& x) {
  const Positions positions = to_positions(x);
  assembler_for(positions);  // binds what is stale
  std::vector<PotentialEnergy> result;
  for (const auto& potential : potentials_) {
    Assembler alone;
    alone.prepare({potential.get()}, active_, positions);
    result.push_back({potential->name(), alone.accumulate(positions, 0, true)});
  }
  return result;
}

Positions to_positions(const Eigen::MatrixX3d& x) {
  return Positions(x);
}

Eigen::MatrixX3d from_positions(const Positions& x) {
  return Eigen::MatrixX3d(x);
}

}  // namespace garment
