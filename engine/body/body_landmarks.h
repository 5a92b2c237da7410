#pragma once
// Landmark heights and limb axes of an A-pose body, found from its horizontal cross-sections, so
// that any A-pose body works without hand-placed markers:
// - crotch: where the two leg loops join into one torso loop;
// - armpits: where the arm loops join the torso (mean of both sides);
// - waist: the narrowest torso (smallest tape-measure circumference) between crotch and armpits,
//   searched in the middle 80 % of that span;
// - hips: the widest torso between crotch and waist;
// - bust: the widest torso between waist and 2 cm below the lower armpit;
// - neck: the base of the neck, where collars sit: below the narrowest section between the
//   armpits and the chin, the height where the circumference has grown to 1.25 × that minimum.
// Axes are least-squares lines through the centroids of the loops of one part: torso (crotch to
// armpits), each arm (its upper 70 %, the hand excluded), each leg (knee-high to crotch).

#include <Eigen/Core>

#include "engine/body/body_cross_sections.h"
#include "engine/body/body_mesh.h"

namespace garment {

struct BodyAxis {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();      // where the part starts (see below)
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  // unit
  double length = 0.0;                                   // metres along direction
};

struct BodyLandmarks {
  double floor = 0.0, top = 0.0;  // lowest and highest y of the body
  double crotch = 0.0, hips = 0.0, waist = 0.0, bust = 0.0, armpits = 0.0, neck = 0.0;  // y
  double centre_x = 0.0;  // the body's plane of symmetry, x = centre_x
  BodyAxis torso;         // origin at waist height, direction up, length crotch → neck base
  BodyAxis left_arm;      // origin at armpit height (under the shoulder), direction toward the
  BodyAxis right_arm;     // wrist, length to the fingertips' height
  BodyAxis left_leg;      // origin at crotch height, direction down toward the ankle, length to
  BodyAxis right_leg;     // the floor
};

// Throws InputError naming the body file when a part cannot be found (not an A-pose human).
BodyLandmarks find_body_landmarks(const BodyMesh& body, const BodySlicer& slicer);

// The loop of the torso in a section: the largest loop that spans the plane of symmetry, or null.
const SectionLoop* torso_loop(const std::vector<SectionLoop>& loops, double centre_x);

// What a tailor's tape round the torso reads at `height`: the convex hull perimeter of the torso's
// loop in the horizontal section there, m (0 where the section has no torso loop). At the waist
// landmark it is the narrowest the torso gets between crotch and armpits (as searched above), so
// a band shorter than it must stretch wherever it sits round the torso.
double torso_girth(const BodySlicer& slicer, double centre_x, double height);

}  // namespace garment
