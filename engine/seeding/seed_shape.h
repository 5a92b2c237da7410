#pragma once
// Seed shape (paper §5.2): the seed pieces start on their body location's surface (wrapped around
// a cylinder or laid on a plane, Fig. 3a) and take their shape by minimising
//   F_init = F_cent + F_up + F_dist + F_def          (Eq. 3–5)
// plus the sewing among the seed's own pieces (a collar in parts, front and back halves) and body
// repulsion, so that the seed ends outside the body, centred and upright.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "engine/core/observer.h"
#include "engine/energy/energy_parameters.h"
#include "engine/seeding/scene.h"
#include "engine/seeding/seed_choice.h"

namespace garment {

struct SeedShapeOptions {
  int iterations = 400;  // ArrangementParameters::seed_iterations in a session
  // Seed bending is stiffer than the arrangement's default (§5.2: "a relatively high default value
  // for the bending stiffness"), by this factor.
  double bending_factor = 10.0;
  // A shaped seed whose edges stretch beyond this (max strain) is caught on the body: it is shaped
  // again from the next SeedStart (see shape_seed).
  double broken_strain = 0.5;
  // An outfit's later garment (session.h): its seed stays outside these triangles (#garment ids,
  // the garments arranged before it) by the one-sided self repulsion of the arrangement (Eq. 12),
  // looked up this far (m): farther than the arrangement's 2 cm, since the seed starts at the
  // body's distance and a loose garment underneath hangs farther out than that.
  std::vector<int> obstacle_triangles;
  double obstacle_search_radius = 0.1;
};

struct SeedShapeReport {
  int iterations = 0;
  double work = 0.0;  // free vertices × iterations of its solves (SolveReport::work)
  double seconds = 0.0;
  double final_energy = 0.0;
  double max_strain = 0.0;  // of the seed's edges, as the termination check measures it
  int attempts = 1;         // starts tried (SeedStart order) until one was not broken
};

// Writes the seed pieces' rows of `positions` (#V×3). Throws InputError when a part names a
// location that is not one of the 15.
SeedShapeReport shape_seed(const Scene& scene, const SeedPlan& plan, const EnergyParameters& energy,
                           Eigen::MatrixX3d& positions, Observer* observer = nullptr,
                           const std::function<void(const Eigen::MatrixX3d&)>& on_iterate = {},
                           const SeedShapeOptions& options = {});

// Where the seed starts. Wrapped: a part on a front plane and one on the back plane sewn to it (a
// bodice's front and back) wrap together round the torso on one ellipse through both planes, their
// side seams meeting at the sides. Under the armpits: the same, lowered so that the side seams
// start 2 cm under the body's armpits at most. Flat: each part lies on its plane. A part on a
// plane alone always lies flat with its vertex mean on the location's centre.
enum class SeedStart { Wrapped, WrappedUnderArmpits, Flat };

// Only the start: the pieces wrapped on or laid onto their locations' surfaces, no solve.
void place_seed_on_surfaces(const Scene& scene, const SeedPlan& plan, double distance,
                            Eigen::MatrixX3d& positions, SeedStart start = SeedStart::Wrapped);

}  // namespace garment
