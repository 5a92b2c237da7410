#include "engine/arrange/seam_drape.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace garment {
namespace {

// One step of the seam: two consecutive outline vertices, both sewn to placed pieces, in the
// pattern and on the placed partners, with the map of offsets from it: 2D tangent and inward
// normal to the 3D tangent T (the chord) and the hanging direction D; `side` is the outside
// normal of the hanging surface there.
struct SeamSegment {
  int first = 0, second = 0;  // piece-local vertex indices
  Eigen::Vector2d rest_start = Eigen::Vector2d::Zero(), rest_end = Eigen::Vector2d::Zero();
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  Eigen::Vector2d tangent = Eigen::Vector2d::Zero(), inward = Eigen::Vector2d::Zero();
  Eigen::Vector3d along = Eigen::Vector3d::Zero(), down = Eigen::Vector3d::Zero();
  Eigen::Vector3d side = Eigen::Vector3d::Zero();
  int previous = -1, next = -1;  // the segments ending at `first` and starting at `second`
};

Eigen::Vector2d left_of(const Eigen::Vector2d& tangent) {
  return {-tangent.y(), tangent.x()};
}

Eigen::Vector3d blend(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double share) {
  return ((1.0 - share) * from + share * to).normalized();
}

}  // namespace

bool drape_from_seam(const Garment& garment, int piece, const std::vector<bool>& placed,
                     const RigidTransform& transform, const SeamDrapeSettings& settings,
                     double rise_above_height, Eigen::MatrixX3d& positions,
                     Eigen::MatrixX3d& outsides) {
  const Piece& info = garment.pieces[piece];
  // Where each seam vertex of the piece goes: the mean of its placed partners.
  const SeamPartners partners = seam_partners(garment, piece, placed, positions);
  const auto rest = [&](int v) -> Eigen::Vector2d { return garment.rest_positions.row(v); };

  std::vector<SeamSegment> segments;
  std::vector<int> starting_at(info.vertex_count, -1), ending_at(info.vertex_count, -1);
  Eigen::Vector2d mean_inward = Eigen::Vector2d::Zero();
  const std::size_t n = info.outline.size();
  for (std::size_t k = 0; k < n; ++k) {
    const int a = info.outline[k] - info.first_vertex;
    const int b = info.outline[(k + 1) % n] - info.first_vertex;
    if (partners.counts[a] == 0 || partners.counts[b] == 0) continue;
    SeamSegment segment;
    segment.first = a;
    segment.second = b;
    segment.rest_start = rest(info.first_vertex + a);
    segment.rest_end = rest(info.first_vertex + b);
    segment.start = partners.means.row(a).transpose();
    segment.end = partners.means.row(b).transpose();
    const Eigen::Vector2d step = segment.rest_end - segment.rest_start;
    const Eigen::Vector3d chord = segment.end - segment.start;
    if (!(step.norm() > 0.0) || !(chord.norm() > 0.0)) continue;
    segment.tangent = step.normalized();
    // The outline is counter-clockwise: the piece lies to the left of it.
    segment.inward = left_of(segment.tangent);
    segment.along = chord.normalized();
    mean_inward += step.norm() * segment.inward;
    starting_at[a] = static_cast<int>(segments.size());
    ending_at[b] = static_cast<int>(segments.size());
    segments.push_back(segment);
  }
  if (segments.size() < 2 || !(mean_inward.norm() > 0.0)) return false;
  mean_inward.normalize();
  for (SeamSegment& segment : segments) {
    segment.previous = ending_at[segment.first];
    segment.next = starting_at[segment.second];
  }

  // Hanging: the piece is cut to go down from the seam (rest frames are upright); rising: up from
  // it (a hood or a standing collar on the neckline). Either way the seam is at the near end of
  // its extent that way.
  const bool hangs = -mean_inward.y() >= settings.hanging_above;
  const bool rises = mean_inward.y() >= settings.rising_above;
  if (!hangs && !rises) return false;
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (int v = info.first_vertex; v < info.first_vertex + info.vertex_count; ++v) {
    const double reach = rest(v).dot(mean_inward);
    lowest = std::min(lowest, reach);
    highest = std::max(highest, reach);
  }
  double seam_reach = 0.0;
  for (const SeamSegment& segment : segments)
    seam_reach += 0.5 * (segment.rest_start + segment.rest_end).dot(mean_inward);
  seam_reach /= static_cast<double>(segments.size());
  if (!(highest > lowest) || (seam_reach - lowest) > settings.seam_extent * (highest - lowest))
    return false;
  Eigen::Vector3d seam_centre = Eigen::Vector3d::Zero();
  for (const SeamSegment& segment : segments)
    seam_centre += 0.5 * (segment.start + segment.end) / static_cast<double>(segments.size());
  if (rises &&
      (highest - seam_reach < settings.rising_reach || seam_centre.y() <= rise_above_height))
    return false;

  // Sideways: the rigid fit sends the piece away from the seam nearly horizontally, neither down
  // it nor up.
  const auto rotated = [&](const Eigen::Vector2d& direction) -> Eigen::Vector3d {
    return transform.rotation * Eigen::Vector3d(direction.x(), direction.y(), 0.0);
  };
  if (hangs && std::abs(rotated(mean_inward).y()) >= settings.sideways_below) return false;

  // Round the body: a seam that runs more up than round is left to the rigid fit.
  Eigen::Vector3d seam_lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d seam_upper = -seam_lower;
  for (const SeamSegment& segment : segments)
    for (const Eigen::Vector3d& point : {segment.start, segment.end}) {
      seam_lower = seam_lower.cwiseMin(point);
      seam_upper = seam_upper.cwiseMax(point);
    }
  const Eigen::Vector3d seam_size = seam_upper - seam_lower;
  if (seam_size.y() > settings.flat_seam_ratio * std::hypot(seam_size.x(), seam_size.z()))
    return false;

  // Straight down for a hanging piece, up for a rising one.
  const Eigen::Vector3d world_away(0.0, hangs ? -1.0 : 1.0, 0.0);
  double outwards = 0.0;
  // The flare of the cone whose development keeps lengths along the seam: a cone of half-angle θ
  // unrolls into a sector that turns sin θ times as much as its base circle, so a straight seam
  // round the body hangs straight down (a pencil or tiered skirt) and a circle skirt's arc would
  // lie flat (capped at the flare angle).
  double turn_in_pattern = 0.0, turn_round_body = 0.0;
  for (const SeamSegment& segment : segments) {
    if (segment.next < 0) continue;
    const SeamSegment& next = segments[segment.next];
    turn_in_pattern +=
        std::atan2(segment.tangent.x() * next.tangent.y() - segment.tangent.y() * next.tangent.x(),
                   segment.tangent.dot(next.tangent));
    const Eigen::Vector2d from(segment.along.x(), segment.along.z());
    const Eigen::Vector2d to(next.along.x(), next.along.z());
    if (from.norm() > 1e-9 && to.norm() > 1e-9)
      turn_round_body += std::atan2(from.x() * to.y() - from.y() * to.x(), from.dot(to));
  }
  const double flare = std::abs(turn_in_pattern) < std::abs(turn_round_body)
                           ? std::min(settings.flare_angle, std::asin(std::abs(turn_in_pattern) /
                                                                      std::abs(turn_round_body)))
                           : settings.flare_angle;
  const double cos_flare = std::cos(flare);
  const double sin_flare = std::sin(flare);
  for (SeamSegment& segment : segments) {
    const Eigen::Vector3d away = rotated(segment.inward);
    Eigen::Vector3d vertical = world_away - world_away.dot(segment.along) * segment.along;
    if (!(vertical.norm() > 1e-6)) vertical = away - away.dot(segment.along) * segment.along;
    vertical.normalize();
    // T × D is the hanging surface's normal, the piece's outside (its rest +z, the outline being
    // counter-clockwise): with out = T × vertical it is `side` below. Hung so, the piece must
    // flare away from the body, where the rigid fit sent it from here; if its outside would face
    // the body instead, the rigid fit stays.
    const Eigen::Vector3d out = segment.along.cross(vertical);
    if (hangs && out.dot(away) < 0.0) return false;
    outwards += out.dot(0.5 * (segment.start + segment.end) - seam_centre);
    segment.down = cos_flare * vertical + sin_flare * out;
    segment.side = cos_flare * out - sin_flare * vertical;
  }

  // A rising piece has no rigid fit to agree with: its outside must face away from the middle
  // of the curve its seam follows round the neck.
  if (rises && !(outwards > 0.0)) return false;

  for (int v = 0; v < info.vertex_count; ++v) {
    const Eigen::Vector2d u = rest(info.first_vertex + v);
    const SeamSegment* nearest = nullptr;
    double nearest_distance = std::numeric_limits<double>::infinity(), lambda = 0.0;
    for (const SeamSegment& segment : segments) {
      const Eigen::Vector2d step = segment.rest_end - segment.rest_start;
      const double at =
          std::clamp((u - segment.rest_start).dot(step) / step.squaredNorm(), 0.0, 1.0);
      const double distance = (u - (segment.rest_start + at * step)).norm();
      if (distance < nearest_distance) {
        nearest_distance = distance;
        lambda = at;
        nearest = &segment;
      }
    }
    Eigen::Vector3d placed_at, side;
    const bool at_start = lambda <= 0.0, at_end = lambda >= 1.0;
    const int neighbour = at_start ? nearest->previous : at_end ? nearest->next : -1;
    if (!at_start && !at_end) {
      // Beside the segment: down from its point, as far as from it in the pattern.
      const Eigen::Vector2d offset =
          u - (nearest->rest_start + lambda * (nearest->rest_end - nearest->rest_start));
      placed_at = nearest->start + lambda * (nearest->end - nearest->start) +
                  offset.dot(nearest->inward) * nearest->down;
      side = nearest->side;
    } else if (neighbour >= 0) {
      // In the fan beyond a corner of the seam: down from the corner, turning from one
      // segment's hanging direction to the other's as the offset turns between their normals.
      const SeamSegment& before = at_start ? segments[neighbour] : *nearest;
      const SeamSegment& after = at_start ? *nearest : segments[neighbour];
      const Eigen::Vector2d offset = u - after.rest_start;
      const double opening = std::acos(std::clamp(before.inward.dot(after.inward), -1.0, 1.0));
      const double turned =
          std::acos(std::clamp(before.inward.dot(offset.normalized()), -1.0, 1.0));
      const double share = opening > 1e-9 ? std::clamp(turned / opening, 0.0, 1.0) : 0.0;
      placed_at = after.start + offset.norm() * blend(before.down, after.down, share);
      side = blend(before.side, after.side, share);
    } else {
      // Beyond an end of the seam: the offset along it continues along its 3D tangent.
      const Eigen::Vector2d offset = u - (at_start ? nearest->rest_start : nearest->rest_end);
      placed_at = (at_start ? nearest->start : nearest->end) +
                  offset.dot(nearest->tangent) * nearest->along +
                  offset.dot(nearest->inward) * nearest->down;
      side = nearest->side;
    }
    positions.row(info.first_vertex + v) = placed_at.transpose();
    outsides.row(info.first_vertex + v) = side.transpose();
  }
  return true;
}

}  // namespace garment
