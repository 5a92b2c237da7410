#pragma once
// The 15 seed locations of the paper (§5.1.2, Fig. 3a): named places on the body where a seed
// piece is first put, each a centre and a surface (cylinder or plane) on which the piece starts
// before the seed optimisation (Eq. 3–5) pulls it onto the body.
//
// The names follow the seed classes of the classifier (neck, waist, front/back chest, front/back
// pelvis) and how patterns cut the torso (GarmentCode splits bodice fronts and backs into left
// and right halves, `left_ftorso` ...):
//   neck               cylinder around the base of the neck           collars, neckbands
//   neck_front         plane at the front of the neck base            front collar halves
//   neck_back          plane at the back of the neck base             back collars, hood backs
//   waist              cylinder around the waist                      waistbands (whole)
//   waist_front        plane at the front of the waist                front waistband
//   waist_back         plane at the back of the waist                 back waistband
//   chest_front        plane over the front of the chest              one-piece bodice front
//   chest_back         plane over the back of the chest               one-piece bodice back
//   chest_front_left   plane over the left half of the chest front    left_ftorso
//   chest_front_right  plane over the right half of the chest front   right_ftorso
//   chest_back_left    plane over the left half of the chest back     left_btorso
//   chest_back_right   plane over the right half of the chest back    right_btorso
//   pelvis             cylinder around the hips                       skirts, one-piece tubes
//   pelvis_front       plane over the front of the pelvis             skirt / trouser fronts
//   pelvis_back        plane over the back of the pelvis              skirt / trouser backs
// Left is the body's left (+x), front is +z. Surfaces touch the body and enclose it over their
// extent: a cylinder's radius reaches the farthest point of the body's sections over its height,
// a plane passes through the most protruding point within its rectangle; the seeding adds its own
// cloth-body clearance.
//
// An optional `<body>.locations.json` next to the body's OBJ overrides landmark heights, axes and
// locations (location_overrides.h).

#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "engine/body/body_cross_sections.h"
#include "engine/body/body_landmarks.h"
#include "engine/body/body_mesh.h"

namespace garment {

enum class LocationSurface { cylinder, plane };

struct BodyLocation {
  std::string name;
  // Cylinder: the point of the axis at mid-height (a piece wrapped around has its centre there).
  // Plane: the point of the plane in front of (or behind) the middle of its rectangle.
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  // Cylinder: its axis, pointing up. Plane: its normal, pointing away from the body.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();
  LocationSurface surface = LocationSurface::plane;
  // The up direction of a piece placed here (= axis for cylinders; in the plane for planes).
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  double radius = 0.0;       // cylinder only, metres
  double half_width = 0.0;   // plane only: the rectangle's half extent across (left-right)
  double half_height = 0.0;  // half extent along `up` (both surfaces)
};

inline constexpr std::array<std::string_view, 15> kBodyLocationNames = {"neck",
                                                                        "neck_front",
                                                                        "neck_back",
                                                                        "waist",
                                                                        "waist_front",
                                                                        "waist_back",
                                                                        "chest_front",
                                                                        "chest_back",
                                                                        "chest_front_left",
                                                                        "chest_front_right",
                                                                        "chest_back_left",
                                                                        "chest_back_right",
                                                                        "pelvis",
                                                                        "pelvis_front",
                                                                        "pelvis_back"};

std::string_view surface_name(LocationSurface surface);  // "cylinder" or "plane"

// The 15 locations, in the order of kBodyLocationNames, from the body and its landmarks.
std::vector<BodyLocation> derive_body_locations(const BodySlicer& slicer,
                                                const BodyLandmarks& landmarks);

}  // namespace garment
