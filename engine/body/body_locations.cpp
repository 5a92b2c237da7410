#include "engine/body/body_locations.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace garment {
namespace {

constexpr double kSectionStep = 0.005;  // metres between the sections a surface is fitted to

struct TorsoFrame {
  Eigen::Vector3d up, front, left;
};

// Points of the torso loops at heights from..to, and the section centroid at `at`.
struct Band {
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d centroid;
  double half_width = 0.0;  // of the section at `at`
};

Band torso_band(const BodySlicer& slicer, double centre_x, double from, double to, double at) {
  Band band;
  for (double y = from; y <= to + 1e-9; y += kSectionStep) {
    const std::vector<SectionLoop> loops = slicer.section(y);
    if (const SectionLoop* torso = torso_loop(loops, centre_x))
      for (const Eigen::Vector2d& p : torso->points)
        band.points.emplace_back(p.x(), y, p.y());
  }
  const std::vector<SectionLoop> loops = slicer.section(at);
  const SectionLoop* torso = torso_loop(loops, centre_x);
  band.centroid = torso ? Eigen::Vector3d(torso->centroid.x(), at, torso->centroid.y())
                        : Eigen::Vector3d(centre_x, at, 0.0);
  band.half_width = torso ? 0.5 * (torso->upper.x() - torso->lower.x()) : 0.0;
  return band;
}

BodyLocation cylinder(std::string_view name, const Band& band, const Eigen::Vector3d& axis,
                      double half_height) {
  BodyLocation location;
  location.name = name;
  location.surface = LocationSurface::cylinder;
  location.center = band.centroid;
  location.axis = location.up = axis;
  location.half_height = half_height;
  for (const Eigen::Vector3d& p : band.points) {
    const Eigen::Vector3d offset = p - band.centroid;
    location.radius = std::max(location.radius, (offset - offset.dot(axis) * axis).norm());
  }
  return location;
}

// A plane facing `normal` through the most protruding band point within the rectangle centred
// `across` metres to the left of the band's centroid.
BodyLocation plane(std::string_view name, const Band& band, const TorsoFrame& frame,
                   const Eigen::Vector3d& normal, double across, double half_width,
                   double half_height) {
  BodyLocation location;
  location.name = name;
  location.surface = LocationSurface::plane;
  location.axis = normal;
  location.up = frame.up;
  location.half_width = half_width;
  location.half_height = half_height;
  const Eigen::Vector3d middle = band.centroid + across * frame.left;
  double reach = 0.0;
  for (const Eigen::Vector3d& p : band.points)
    if (std::abs((p - middle).dot(frame.left)) <= half_width)
      reach = std::max(reach, (p - middle).dot(normal));
  location.center = middle + reach * normal;
  return location;
}

}  // namespace

std::string_view surface_name(LocationSurface surface) {
  return surface == LocationSurface::cylinder ? "cylinder" : "plane";
}

std::vector<BodyLocation> derive_body_locations(const BodySlicer& slicer,
                                                const BodyLandmarks& marks) {
  TorsoFrame frame;
  frame.up = marks.torso.direction.normalized();
  frame.front = (Eigen::Vector3d::UnitZ() - frame.up.z() * frame.up).normalized();
  frame.left = frame.up.cross(frame.front);
  const double centre_x = marks.centre_x;

  // The neck leans forward: its axis runs through the centroids of its sections, unless they
  // are too irregular to say (then it follows the torso).
  const Band neck = torso_band(slicer, centre_x, marks.neck, marks.neck + 0.03, marks.neck + 0.015);
  const Band neck_top =
      torso_band(slicer, centre_x, marks.neck + 0.04, marks.neck + 0.04, marks.neck + 0.04);
  const Band neck_bottom = torso_band(slicer, centre_x, marks.neck, marks.neck, marks.neck);
  Eigen::Vector3d neck_axis = (neck_top.centroid - neck_bottom.centroid).normalized();
  if (!(neck_axis.dot(frame.up) > std::cos(35.0 * M_PI / 180.0))) neck_axis = frame.up;

  const Band waist =
      torso_band(slicer, centre_x, marks.waist - 0.025, marks.waist + 0.025, marks.waist);
  const Band waist_planes =
      torso_band(slicer, centre_x, marks.waist - 0.03, marks.waist + 0.03, marks.waist);
  const Band chest = torso_band(slicer, centre_x, marks.waist, marks.neck, marks.bust);
  const Band pelvis = torso_band(slicer, centre_x, marks.crotch + 0.01, marks.waist, marks.hips);

  const double chest_half_height = 0.5 * (marks.neck - marks.waist);
  const double pelvis_half_height = 0.5 * (marks.waist - marks.crotch);
  const Eigen::Vector3d front = frame.front, back = -frame.front;
  const double chest_half_width = chest.half_width, half = 0.5 * chest.half_width;

  return {
      cylinder("neck", neck, neck_axis, 0.015),
      plane("neck_front", neck, frame, front, 0.0, neck.half_width, 0.03),
      plane("neck_back", neck, frame, back, 0.0, neck.half_width, 0.03),
      cylinder("waist", waist, frame.up, 0.025),
      plane("waist_front", waist_planes, frame, front, 0.0, waist_planes.half_width, 0.03),
      plane("waist_back", waist_planes, frame, back, 0.0, waist_planes.half_width, 0.03),
      plane("chest_front", chest, frame, front, 0.0, chest_half_width, chest_half_height),
      plane("chest_back", chest, frame, back, 0.0, chest_half_width, chest_half_height),
      plane("chest_front_left", chest, frame, front, half, half, chest_half_height),
      plane("chest_front_right", chest, frame, front, -half, half, chest_half_height),
      plane("chest_back_left", chest, frame, back, half, half, chest_half_height),
      plane("chest_back_right", chest, frame, back, -half, half, chest_half_height),
      cylinder("pelvis", pelvis, frame.up, pelvis_half_height),
      plane("pelvis_front", pelvis, frame, front, 0.0, pelvis.half_width, pelvis_half_height),
      plane("pelvis_back", pelvis, frame, back, 0.0, pelvis.half_width, pelvis_half_height),
  };
}

}  // namespace garment
