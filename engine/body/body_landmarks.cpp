#include "engine/body/body_landmarks.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.h"

namespace garment {
namespace {

constexpr double kScanStep = 0.005;      // metres between the scanned sections
constexpr double kSpanMargin = 0.02;     // a torso loop reaches this far past the symmetry plane
constexpr double kTorsoMinArea = 20e-4;  // m²: below this a spanning loop is a chin or a nose
constexpr double kLimbMinArea = 5e-4;    // m²: fingers and ear lobes are smaller
constexpr double kArmOffset = 0.12;      // arm loops lie at least this far from the symmetry plane

struct Slice {
  double y;
  std::vector<SectionLoop> loops;
};

// The largest loop on one side (+1 left, −1 right) whose centroid is at least `offset` from the
// symmetry plane and that is not the torso.
const SectionLoop* side_loop(const std::vector<SectionLoop>& loops, const SectionLoop* torso,
                             double centre_x, int side, double offset, double min_area) {
  for (const SectionLoop& loop : loops)  // largest first
    if (&loop != torso && loop.area >= min_area && side * (loop.centroid.x() - centre_x) > offset)
      return &loop;
  return nullptr;
}

// The height between `low` and `high` where `holds` changes its answer, to 1/1024 of the gap.
double refine(double low, double high, const std::function<bool(double)>& holds) {
  const bool low_value = holds(low);
  for (int iteration = 0; iteration < 10; ++iteration) {
    const double middle = 0.5 * (low + high);
    (holds(middle) == low_value ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

// Least-squares line x(y), z(y) through loop centroids; returns the unit direction (y > 0) and
// the point at height `at`.
std::pair<Eigen::Vector3d, Eigen::Vector3d> fit_line(const std::vector<Eigen::Vector3d>& points,
                                                     double at) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points)
    mean += p;
  mean /= static_cast<double>(points.size());
  double yy = 0.0, xy = 0.0, zy = 0.0;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d d = p - mean;
    yy += d.y() * d.y();
    xy += d.x() * d.y();
    zy += d.z() * d.y();
  }
  const double slope_x = yy > 0.0 ? xy / yy : 0.0, slope_z = yy > 0.0 ? zy / yy : 0.0;
  const Eigen::Vector3d direction = Eigen::Vector3d(slope_x, 1.0, slope_z).normalized();
  const Eigen::Vector3d point(mean.x() + slope_x * (at - mean.y()), at,
                              mean.z() + slope_z * (at - mean.y()));
  return {direction, point};
}

Eigen::Vector3d centroid_3d(const SectionLoop& loop, double y) {
  return {loop.centroid.x(), y, loop.centroid.y()};
}

}  // namespace

const SectionLoop* torso_loop(const std::vector<SectionLoop>& loops, double centre_x) {
  for (const SectionLoop& loop : loops)  // largest first
    if (loop.area >= kTorsoMinArea && loop.lower.x() < centre_x - kSpanMargin &&
        loop.upper.x() > centre_x + kSpanMargin)
      return &loop;
  return nullptr;
}

double torso_girth(const BodySlicer& slicer, double centre_x, double height) {
  const std::vector<SectionLoop> loops = slicer.section(height);
  const SectionLoop* torso = torso_loop(loops, centre_x);
  return torso ? torso->hull_perimeter : 0.0;
}

BodyLandmarks find_body_landmarks(const BodyMesh& body, const BodySlicer& slicer) {
  const auto fail = [&](const std::string& what) {
    throw_input_error(body.source, "body landmarks",
                      "cannot find " + what + ": not a human body in A-pose (y up, facing +z)");
  };
  BodyLandmarks marks;
  const Eigen::Vector3d lower = body.lower_corner(), upper = body.upper_corner();
  marks.floor = lower.y();
  marks.top = upper.y();
  marks.centre_x = 0.5 * (lower.x() + upper.x());
  const double height = marks.top - marks.floor;
  const double centre = marks.centre_x;

  std::vector<Slice> slices;
  for (double y = marks.floor + kScanStep; y < marks.top; y += kScanStep)
    slices.push_back({y, slicer.section(y)});
  const auto torso_at = [&](const Slice& slice) { return torso_loop(slice.loops, centre); };
  const auto has_torso = [&](double y) { return torso_loop(slicer.section(y), centre) != nullptr; };

  // Crotch: scanning up from knee height, the first section with one loop across the middle.
  std::optional<double> crotch;
  for (std::size_t s = 1; s < slices.size() && !crotch; ++s)
    if (slices[s].y > marks.floor + 0.25 * height && slices[s].y < marks.floor + 0.7 * height &&
        torso_at(slices[s]) && !torso_at(slices[s - 1]))
      crotch = refine(slices[s - 1].y, slices[s].y, has_torso);
  if (!crotch) fail("the crotch (where the legs join)");
  marks.crotch = *crotch;

  // Armpits: per side, the highest section above the crotch that still has a separate arm loop.
  double armpit[2];
  double fingertips[2];
  for (int side_index = 0; side_index < 2; ++side_index) {
    const int side = side_index == 0 ? 1 : -1;
    const auto has_arm = [&](const std::vector<SectionLoop>& loops) {
      return side_loop(loops, torso_loop(loops, centre), centre, side, kArmOffset, kLimbMinArea) !=
             nullptr;
    };
    std::optional<std::size_t> highest, lowest;
    for (std::size_t s = 0; s + 1 < slices.size(); ++s) {
      if (slices[s].y <= marks.crotch) continue;
      if (has_arm(slices[s].loops)) highest = s;
      if (!lowest && side_loop(slices[s].loops, torso_at(slices[s]), centre, side, kArmOffset, 0.0))
        lowest = s;
    }
    if (!highest || !lowest || slices[*highest].y < marks.crotch + 0.1 * height)
      fail(side > 0 ? "the left arm" : "the right arm");
    armpit[side_index] = refine(slices[*highest].y, slices[*highest + 1].y,
                                [&](double y) { return has_arm(slicer.section(y)); });
    fingertips[side_index] = slices[*lowest].y;
  }
  marks.armpits = 0.5 * (armpit[0] + armpit[1]);
  const double low_armpit = std::min(armpit[0], armpit[1]);
  const double high_armpit = std::max(armpit[0], armpit[1]);

  // Circumference profile of the torso.
  const auto extreme = [&](double from, double to, bool largest) {
    std::optional<double> best_y;
    double best = 0.0;
    for (const Slice& slice : slices) {
      if (slice.y < from || slice.y > to) continue;
      const SectionLoop* torso = torso_at(slice);
      if (!torso) continue;
      if (!best_y || (largest ? torso->hull_perimeter > best : torso->hull_perimeter < best)) {
        best = torso->hull_perimeter;
        best_y = slice.y;
      }
    }
    return best_y;
  };
  const double span = low_armpit - marks.crotch;
  const std::optional<double> waist =
      extreme(marks.crotch + 0.1 * span, low_armpit - 0.1 * span, false);
  if (!waist) fail("the waist");
  marks.waist = *waist;
  const std::optional<double> hips =
      extreme(marks.crotch + kScanStep, marks.waist - kScanStep, true);
  const std::optional<double> bust = extreme(marks.waist + kScanStep, low_armpit - 0.02, true);
  if (!hips) fail("the hips");
  if (!bust) fail("the bust");
  marks.hips = *hips;
  marks.bust = *bust;

  // Neck base: below the narrowest section between the shoulders and the chin, where the
  // circumference has grown back to 1.25 × that minimum.
  const std::optional<double> narrowest = extreme(high_armpit + 0.03, marks.top - 0.15, false);
  if (!narrowest) fail("the neck");
  const double narrowest_perimeter = torso_girth(slicer, centre, *narrowest);
  const auto wider = [&](double y) {
    return torso_girth(slicer, centre, y) > 1.25 * narrowest_perimeter;
  };
  std::optional<double> neck;
  for (double y = *narrowest; y > high_armpit && !neck; y -= kScanStep)
    if (wider(y - kScanStep)) neck = refine(y - kScanStep, y, wider);
  if (!neck) fail("the base of the neck");
  marks.neck = *neck;

  // Axes.
  std::vector<Eigen::Vector3d> centroids;
  for (const Slice& slice : slices)
    if (slice.y > marks.crotch + 0.05 && slice.y < low_armpit - 0.03)
      if (const SectionLoop* torso = torso_at(slice))
        centroids.push_back(centroid_3d(*torso, slice.y));
  if (centroids.size() < 2) fail("the torso");
  const auto [torso_direction, torso_origin] = fit_line(centroids, marks.waist);
  marks.torso.origin = torso_origin;
  marks.torso.direction = torso_direction;
  marks.torso.length = (marks.neck - marks.crotch) / torso_direction.y();

  for (int side_index = 0; side_index < 2; ++side_index) {
    const int side = side_index == 0 ? 1 : -1;
    centroids.clear();
    const double from =
        fingertips[side_index] + 0.3 * (armpit[side_index] - fingertips[side_index]);
    for (const Slice& slice : slices)
      if (slice.y > from && slice.y < armpit[side_index] - 0.02)
        if (const SectionLoop* arm =
                side_loop(slice.loops, torso_at(slice), centre, side, kArmOffset, kLimbMinArea))
          centroids.push_back(centroid_3d(*arm, slice.y));
    if (centroids.size() < 2) fail(side > 0 ? "the left arm's axis" : "the right arm's axis");
    const auto [arm_direction, arm_origin] = fit_line(centroids, armpit[side_index]);
    BodyAxis& arm = side > 0 ? marks.left_arm : marks.right_arm;
    arm.origin = arm_origin;
    arm.direction = -arm_direction;
    arm.length = (armpit[side_index] - fingertips[side_index]) / arm_direction.y();

    centroids.clear();
    for (const Slice& slice : slices)
      if (slice.y > marks.floor + 0.28 * height && slice.y < marks.crotch - 0.03)
        if (const SectionLoop* leg =
                side_loop(slice.loops, nullptr, centre, side, 0.0, kLimbMinArea))
          centroids.push_back(centroid_3d(*leg, slice.y));
    if (centroids.size() < 2) fail(side > 0 ? "the left leg" : "the right leg");
    const auto [leg_direction, leg_origin] = fit_line(centroids, marks.crotch);
    BodyAxis& leg = side > 0 ? marks.left_leg : marks.right_leg;
    leg.origin = leg_origin;
    leg.direction = -leg_direction;
    leg.length = (marks.crotch - marks.floor) / leg_direction.y();
  }
  return marks;
}

}  // namespace garment
