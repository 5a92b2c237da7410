#include "engine/start_shapes/seam_drape.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <tuple>
#include <utility>

namespace garment {
namespace {

// One step of the seam: two consecutive outline vertices, both sewn to placed pieces, in the
// pattern and on the placed partners, with the map of offsets from it: 2D tangent and inward
// normal to the 3D tangent T (the chord) and the rising direction D; `side` is the outside
// normal of the rising surface there.
struct SeamSegment {
  int first = 0, second = 0;  // piece-local vertex indices
  Eigen::Vector2d rest_start = Eigen::Vector2d::Zero(), rest_end = Eigen::Vector2d::Zero();
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  Eigen::Vector2d tangent = Eigen::Vector2d::Zero(), inward = Eigen::Vector2d::Zero();
  Eigen::Vector3d along = Eigen::Vector3d::Zero(), up = Eigen::Vector3d::Zero();
  Eigen::Vector3d side = Eigen::Vector3d::Zero();
  int previous = -1, next = -1;  // the segments ending at `first` and starting at `second`
};

Eigen::Vector2d left_of(const Eigen::Vector2d& tangent) {
  return {-tangent.y(), tangent.x()};
}

// The angle from `from` to `to`, counter-clockwise positive.
double signed_angle(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  return std::atan2(from.x() * to.y() - from.y() * to.x(), from.dot(to));
}

Eigen::Vector3d blend(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double share) {
  return ((1.0 - share) * from + share * to).normalized();
}

// The point of the torso's axis at `height`.
Eigen::Vector3d axis_at(const BodyAxis& axis, double height) {
  if (std::abs(axis.direction.y()) < 1e-6) return axis.origin;
  return axis.origin + (height - axis.origin.y()) / axis.direction.y() * axis.direction;
}

// The seam as one run of the outline: from the end of the longest stretch of outline that is not
// sewn to placed pieces round to its start, so that short unsewn stretches inside (a gap between
// two partners) belong to it, placed by arc length between the sewn vertices round them. A dart
// is crossed by its mouth instead: its sides close in the garment, and walked round, a pencil
// skirt's 12 cm waist darts put vertices 15 cm below the waist 3 cm from the seam and folded the
// piece up through itself (gc_0081: 10 771 edge-triangle contacts in its front).
struct SeamRun {
  std::vector<Eigen::Vector2d> rest;
  std::vector<Eigen::Vector3d> placed;
  std::vector<double> along;  // arc length in the pattern from the run's start
  bool crosses_darts = false;
};

SeamRun seam_run(const Garment& garment, const Piece& info, const SeamPartners& partners) {
  const std::vector<int>& outline = info.outline;
  const std::size_t n = outline.size();
  const auto rest = [&](std::size_t k) -> Eigen::Vector2d {
    return garment.rest_positions.row(outline[k % n]);
  };
  const auto sewn = [&](std::size_t k) {
    return partners.counts[outline[k % n] - info.first_vertex] > 0;
  };
  std::vector<char> in_dart(info.vertex_count, 0);
  for (Eigen::Index k = 0; k < garment.dart_pairs.rows(); ++k)
    for (int side = 0; side < 2; ++side) {
      const int v = garment.dart_pairs(k, side) - info.first_vertex;
      if (v >= 0 && v < info.vertex_count) in_dart[v] = 1;
    }
  // The longest unsewn stretch ends at a sewn vertex `first`: the run starts there.
  std::size_t first = n;
  double longest = -1.0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!sewn(k)) continue;
    double stretch = 0.0;
    std::size_t j = k;
    do {
      stretch += (rest(j + n - 1) - rest(j)).norm();
      j = (j + n - 1) % n;
    } while (!sewn(j));
    if (stretch > longest) {
      longest = stretch;
      first = k;
    }
  }
  SeamRun run;
  if (first == n) return run;
  std::size_t last = first;
  for (std::size_t k = first; k < first + n; ++k)
    if (sewn(k)) last = k;
  std::vector<char> known;
  for (std::size_t k = first; k <= last; ++k) {
    if (!sewn(k) && in_dart[outline[k % n] - info.first_vertex]) {
      run.crosses_darts = true;
      continue;
    }
    run.along.push_back(run.rest.empty() ? 0.0
                                         : run.along.back() + (rest(k) - run.rest.back()).norm());
    run.rest.push_back(rest(k));
    known.push_back(sewn(k));
    run.placed.push_back(
        sewn(k) ? Eigen::Vector3d(partners.means.row(outline[k % n] - info.first_vertex))
                : Eigen::Vector3d::Zero());
  }
  for (std::size_t k = 0, before = 0; k < run.rest.size(); ++k) {
    if (known[k]) {
      before = k;
      continue;
    }
    std::size_t after = k;
    while (!known[after])
      ++after;
    const double share =
        (run.along[k] - run.along[before]) / (run.along[after] - run.along[before]);
    run.placed[k] = (1.0 - share) * run.placed[before] + share * run.placed[after];
  }
  return run;
}

// A piece's seam with the placed pieces seen from the torso's axis: per seam vertex the level
// direction from the axis to it, and the signed angle those turn through round the vertical.
struct SeamRoundAxis {
  SeamRun run;
  std::vector<Eigen::Vector3d> radial;
  double turn = 0.0;
};

// Nothing when the seam has fewer than two vertices or one lies on the axis.
std::optional<SeamRoundAxis> seam_round_axis(const Garment& garment, int piece,
                                             const SeamPartners& partners, const BodyAxis& torso) {
  SeamRoundAxis seam{seam_run(garment, garment.pieces[piece], partners), {}, 0.0};
  if (seam.run.placed.size() < 2) return std::nullopt;
  for (const Eigen::Vector3d& point : seam.run.placed) {
    Eigen::Vector3d away = point - axis_at(torso, point.y());
    away.y() = 0.0;
    if (!(away.norm() > 1e-9)) return std::nullopt;
    seam.radial.push_back(away.normalized());
  }
  for (std::size_t k = 0; k + 1 < seam.radial.size(); ++k)
    seam.turn += std::atan2(seam.radial[k].cross(seam.radial[k + 1]).y(),
                            seam.radial[k].dot(seam.radial[k + 1]));
  return seam;
}

// Whether `piece` makes a leg's tube: sewn along two seams to another piece that hangs from the
// placed pieces too, the two make a tube, and a tube round the torso takes the whole of the seam
// round the body (a two-panel skirt's front and back turn 2π round the axis together), one round
// a leg only its side of it (a trouser leg's front and back, π; the two backs, sewn down the
// crotch in two stitches, too). Hung round the torso, trousers would start as a skirt: of the
// trousers of the 500 GarmentCode patterns, 4 were lost so and 2 gained. own_turn: the turn of
// the piece's own seam round the axis (SeamRoundAxis).
bool makes_leg_tube(const Garment& garment, int piece, double own_turn,
                    const std::vector<bool>& placed, const Eigen::MatrixX3d& positions,
                    const BodyAxis& torso) {
  std::vector<int> shared_seams(garment.pieces.size(), 0);
  for (const StitchPairs& range : garment.stitches) {
    const Stitch& stitch = garment.pattern.stitches[range.stitch];
    if (stitch.a.panel == piece && stitch.b.panel != piece) ++shared_seams[stitch.b.panel];
    if (stitch.b.panel == piece && stitch.a.panel != piece) ++shared_seams[stitch.a.panel];
  }
  for (int other = 0; other < static_cast<int>(garment.pieces.size()); ++other) {
    if (other == piece || shared_seams[other] < 2 || placed[other]) continue;
    const std::optional<SeamRoundAxis> other_seam =
        seam_round_axis(garment, other, seam_partners(garment, other, placed, positions), torso);
    // Half way between a leg's π and the torso's 2π.
    if (other_seam && std::abs(own_turn + other_seam->turn) < 1.5 * std::numbers::pi) return true;
  }
  return false;
}

// A hanging piece as a cone round the torso's axis (see the header), from its seam seen from the
// axis: returns false, leaving positions and outsides as they are, when its outside would face
// the axis.
bool hang_round_torso(const Garment& garment, int piece, const SeamRoundAxis& seam,
                      const SeamDrapeSettings& settings, Eigen::MatrixX3d& positions,
                      Eigen::MatrixX3d& outsides) {
  const Piece& info = garment.pieces[piece];
  const SeamRun& run = seam.run;
  const std::vector<Eigen::Vector3d>& radial = seam.radial;
  const std::size_t m = run.rest.size();
  if (!(run.along.back() > 0.0)) return false;
  const double length = run.along.back();
  const double turn_round_body = seam.turn;

  double facing = 0.0;
  for (std::size_t k = 0; k + 1 < m; ++k)
    // The hanging surface's normal T × D with D straight down: outwards when the seam runs round
    // the axis the way the outline does in the pattern.
    facing += (run.placed[k + 1] - run.placed[k]).cross(-Eigen::Vector3d::UnitY()).dot(radial[k]);
  if (!(facing > 0.0)) return false;

  // Each vertex: how far from the seam in the pattern (its depth) and where round the seam's
  // parallel curve at that depth (its round): the arc length to the nearest seam point, plus the
  // depth times the seam's turn up to there, since a parallel curve on the piece's side of a
  // seam that turns away from the piece (a circle skirt's waist) gains that much length at each
  // corner; past the seam's ends, on along their tangents.
  const auto tangent = [&](std::size_t k) -> Eigen::Vector2d {
    return (run.rest[k + 1] - run.rest[k]).normalized();
  };
  // gained[k]: the turn away from the piece from the seam's start to segment k (the piece is on
  // the left, so a clockwise turn).
  std::vector<double> gained(m - 1, 0.0);
  for (std::size_t k = 1; k + 1 < m; ++k)
    gained[k] = gained[k - 1] - signed_angle(tangent(k - 1), tangent(k));
  Eigen::VectorXd round(info.vertex_count), depth(info.vertex_count);
  for (int v = 0; v < info.vertex_count; ++v) {
    const Eigen::Vector2d u = garment.rest_positions.row(info.first_vertex + v);
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < m; ++k) {
      const Eigen::Vector2d step = run.rest[k + 1] - run.rest[k];
      if (!(step.squaredNorm() > 0.0)) continue;
      const double at = std::clamp((u - run.rest[k]).dot(step) / step.squaredNorm(), 0.0, 1.0);
      const Eigen::Vector2d offset = u - (run.rest[k] + at * step);
      if (offset.norm() >= nearest) continue;
      nearest = offset.norm();
      const Eigen::Vector2d direction = tangent(k);
      if ((k == 0 && at <= 0.0) || (k + 2 == m && at >= 1.0)) {
        depth(v) = offset.dot(left_of(direction));
        round(v) = (at <= 0.0 ? 0.0 : length + gained[k] * depth(v)) + offset.dot(direction);
      } else if (at > 0.0 && at < 1.0) {
        depth(v) = nearest;
        round(v) = run.along[k] + at * step.norm() + gained[k] * nearest;
      } else {
        // In the fan beyond the corner between this segment and its neighbour: the turn so far
        // goes on from one segment's to the other's as the offset turns between their normals.
        const std::size_t before = at <= 0.0 ? k - 1 : k, after = before + 1;
        const double corner_turn = gained[after] - gained[before];
        const double turned = -signed_angle(left_of(tangent(before)), offset);
        depth(v) = nearest;
        round(v) =
            run.along[after] + (gained[before] + std::clamp(turned, std::min(0.0, corner_turn),
                                                            std::max(0.0, corner_turn))) *
                                   nearest;
      }
    }
    depth(v) = std::max(depth(v), 0.0);
  }

  // The piece's extent round the seam at each depth: between two lines from the seam's ends,
  // opening as fast as the piece's outline needs somewhere below 2 cm (a flared panel's sides, a
  // circle skirt's radial edges; a hem that rises towards the sides does not close them). The
  // few vertices nearer the seam beyond its ends are held at the lines.
  constexpr double kLeastDepth = 0.02;
  double start_slope = 0.0, end_slope = 0.0;
  for (int v = 0; v < info.vertex_count; ++v) {
    if (depth(v) < kLeastDepth) continue;
    start_slope = std::min(start_slope, round(v) / depth(v));
    end_slope = std::max(end_slope, (round(v) - length) / depth(v));
  }

  // The flare of the cone whose development keeps lengths round it: its rows widen by
  // (end_slope − start_slope) per metre of depth, and the cone's by sin θ times the seam's turn
  // round the axis.
  const double widening = end_slope - start_slope;
  const double flare =
      std::abs(turn_round_body) > 1e-6
          ? std::min(settings.flare_angle,
                     std::asin(std::min(1.0, widening / std::abs(turn_round_body))))
          : settings.flare_angle;
  const double cos_flare = std::cos(flare), sin_flare = std::sin(flare);

  // Where round the placed seam a vertex goes: on the seam, at its partners, by the pattern's arc
  // length between the seam's vertices. Across a dart's mouth that arc is one point of the placed
  // seam, and the strip of cloth below the mouth would hang as one line down to the hem: there
  // rows deeper than kEvenBelow go round the placed seam evenly by its arc length, with a blend
  // between.
  constexpr double kEvenBelow = 0.05;
  std::vector<double> placed_along(m, 0.0);
  for (std::size_t k = 1; k < m; ++k)
    placed_along[k] = placed_along[k - 1] + (run.placed[k] - run.placed[k - 1]).norm();
  // The seam's segment [k − 1, k] holding arc length `at` of `arcs` (run.along or placed_along),
  // and how far along it.
  const auto segment_at = [&](const std::vector<double>& arcs, double at) {
    const std::size_t k = std::clamp<std::size_t>(
        std::upper_bound(arcs.begin(), arcs.end(), at) - arcs.begin(), 1, m - 1);
    const double step = arcs[k] - arcs[k - 1];
    return std::pair{k, step > 0.0 ? (at - arcs[k - 1]) / step : 0.0};
  };
  for (int v = 0; v < info.vertex_count; ++v) {
    const double start = start_slope * depth(v), end = length + end_slope * depth(v);
    const double share = std::clamp((round(v) - start) / (end - start), 0.0, 1.0);
    const double even = run.crosses_darts ? std::clamp(depth(v) / kEvenBelow, 0.0, 1.0) : 0.0;
    auto [b, t] = segment_at(run.along, share * length);
    if (even > 0.0) {
      const double at_seam = (1.0 - t) * placed_along[b - 1] + t * placed_along[b];
      std::tie(b, t) =
          segment_at(placed_along, (1.0 - even) * at_seam + even * share * placed_along.back());
    }
    const std::size_t a = b - 1;
    const Eigen::Vector3d seam_point = (1.0 - t) * run.placed[a] + t * run.placed[b];
    const Eigen::Vector3d out = ((1.0 - t) * radial[a] + t * radial[b]).normalized();
    const Eigen::Vector3d down = cos_flare * -Eigen::Vector3d::UnitY() + sin_flare * out;
    positions.row(info.first_vertex + v) = (seam_point + depth(v) * down).transpose();
    outsides.row(info.first_vertex + v) =
        (cos_flare * out + sin_flare * Eigen::Vector3d::UnitY()).transpose();
  }
  return true;
}

}  // namespace

bool drape_from_seam(const Garment& garment, int piece, const std::vector<bool>& placed,
                     const RigidTransform& transform, const SeamDrapeSettings& settings,
                     const BodyLandmarks& landmarks, Eigen::MatrixX3d& positions,
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
      (highest - seam_reach < settings.rising_reach || seam_centre.y() <= landmarks.armpits))
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
  if (hangs) {
    const std::optional<SeamRoundAxis> seam =
        seam_round_axis(garment, piece, partners, landmarks.torso);
    return seam &&
           !makes_leg_tube(garment, piece, seam->turn, placed, positions, landmarks.torso) &&
           hang_round_torso(garment, piece, *seam, settings, positions, outsides);
  }

  const Eigen::Vector3d world_away = Eigen::Vector3d::UnitY();
  double outwards = 0.0;
  // The flare of the cone whose development keeps lengths along the seam: a cone of half-angle θ
  // unrolls into a sector that turns sin θ times as much as its base circle.
  double turn_in_pattern = 0.0, turn_round_body = 0.0;
  for (const SeamSegment& segment : segments) {
    if (segment.next < 0) continue;
    const SeamSegment& next = segments[segment.next];
    turn_in_pattern += signed_angle(segment.tangent, next.tangent);
    const Eigen::Vector2d from(segment.along.x(), segment.along.z());
    const Eigen::Vector2d to(next.along.x(), next.along.z());
    if (from.norm() > 1e-9 && to.norm() > 1e-9) turn_round_body += signed_angle(from, to);
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
    // T × D is the rising surface's normal, the piece's outside (its rest +z, the outline being
    // counter-clockwise): with out = T × vertical it is `side` below.
    const Eigen::Vector3d out = segment.along.cross(vertical);
    outwards += out.dot(0.5 * (segment.start + segment.end) - seam_centre);
    segment.up = cos_flare * vertical + sin_flare * out;
    segment.side = cos_flare * out - sin_flare * vertical;
  }

  // Its outside must face away from the middle of the curve its seam follows round the neck.
  if (!(outwards > 0.0)) return false;

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
      // Beside the segment: up from its point, as far as from it in the pattern.
      const Eigen::Vector2d offset =
          u - (nearest->rest_start + lambda * (nearest->rest_end - nearest->rest_start));
      placed_at = nearest->start + lambda * (nearest->end - nearest->start) +
                  offset.dot(nearest->inward) * nearest->up;
      side = nearest->side;
    } else if (neighbour >= 0) {
      // In the fan beyond a corner of the seam: up from the corner, turning from one
      // segment's rising direction to the other's as the offset turns between their normals.
      const SeamSegment& before = at_start ? segments[neighbour] : *nearest;
      const SeamSegment& after = at_start ? *nearest : segments[neighbour];
      const Eigen::Vector2d offset = u - after.rest_start;
      const double opening = std::acos(std::clamp(before.inward.dot(after.inward), -1.0, 1.0));
      const double turned =
          std::acos(std::clamp(before.inward.dot(offset.normalized()), -1.0, 1.0));
      const double share = opening > 1e-9 ? std::clamp(turned / opening, 0.0, 1.0) : 0.0;
      placed_at = after.start + offset.norm() * blend(before.up, after.up, share);
      side = blend(before.side, after.side, share);
    } else {
      // Beyond an end of the seam: the offset along it continues along its 3D tangent.
      const Eigen::Vector2d offset = u - (at_start ? nearest->rest_start : nearest->rest_end);
      placed_at = (at_start ? nearest->start : nearest->end) +
                  offset.dot(nearest->tangent) * nearest->along +
                  offset.dot(nearest->inward) * nearest->up;
      side = nearest->side;
    }
    positions.row(info.first_vertex + v) = placed_at.transpose();
    outsides.row(info.first_vertex + v) = side.transpose();
  }
  return true;
}

}  // namespace garment
