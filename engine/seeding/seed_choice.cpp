#include "engine/seeding/seed_choice.h"

#include <algorithm>
#include <limits>
#include <set>

#include "engine/core/error.h"
#include "engine/quality/expected_region.h"
#include "engine/seeding/seed_layout.h"
#include "engine/seeding/sewing_relationship.h"

namespace garment {
namespace {

// A class per group (#groups): the classifier's most probable one, or a seed choice's correction.
using GroupClasses = std::vector<SeedClass>;

GroupClasses most_probable_classes(const PieceClassification& classification) {
  GroupClasses classes;
  for (int g = 0; g < static_cast<int>(classification.groups.size()); ++g)
    classes.push_back(classification.group_class(g));
  return classes;
}

// Groups of the class `wanted`, connected by stitches to `start` through groups of that class.
std::vector<int> connected_groups_of_class(const Garment& garment,
                                           const PieceClassification& classification,
                                           const GroupClasses& classes, int start,
                                           SeedClass wanted) {
  std::set<int> found{start};
  std::vector<int> frontier{start};
  while (!frontier.empty()) {
    const int group = frontier.back();
    frontier.pop_back();
    for (const StitchPairs& range : garment.stitches) {
      const Stitch& stitch = garment.pattern.stitches[range.stitch];
      const int a = classification.piece_group[stitch.a.panel],
                b = classification.piece_group[stitch.b.panel];
      for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
        if (from != group || found.count(to) || classes[to] != wanted) continue;
        found.insert(to);
        frontier.push_back(to);
      }
    }
  }
  return {found.begin(), found.end()};
}

std::vector<int> pieces_of(const PieceClassification& classification,
                           const std::vector<int>& groups) {
  std::vector<int> pieces;
  for (int group : groups)
    pieces.insert(pieces.end(), classification.groups[group].begin(),
                  classification.groups[group].end());
  std::sort(pieces.begin(), pieces.end());
  return pieces;
}

// All groups of a class, most probable first.
std::vector<int> groups_of_class(const PieceClassification& classification,
                                 const GroupClasses& classes, SeedClass wanted) {
  std::vector<int> groups;
  for (int g = 0; g < static_cast<int>(classes.size()); ++g)
    if (classes[g] == wanted) groups.push_back(g);
  std::stable_sort(groups.begin(), groups.end(), [&](int a, int b) {
    return classification.probability(a, wanted) > classification.probability(b, wanted);
  });
  return groups;
}

// A garment has a front and a back. When the classifier puts every group of a front/back pair of
// classes on one side, the group most probably of the other side, after the most probable group of
// this side, goes there if the classifier gives it at least kOtherSideProbability, or if the
// classifier cannot tell it from the most probable group at all (the identical front and back
// panels of a plain skirt get the same probabilities however sure it is of the side: left on one
// side, both panels go to it, one on top of the other).
constexpr double kOtherSideProbability = 0.25;

bool indistinguishable(const PieceClassification& classification, int a, int b) {
  return (classification.probabilities.row(a) - classification.probabilities.row(b))
             .cwiseAbs()
             .maxCoeff() < 1e-9;
}

void complete_front_and_back(const PieceClassification& classification, GroupClasses& classes,
                             SeedClass front, SeedClass back) {
  for (const auto& [present, missing] : {std::pair{front, back}, std::pair{back, front}}) {
    const std::vector<int> groups = groups_of_class(classification, classes, present);
    if (groups.size() < 2 || !groups_of_class(classification, classes, missing).empty()) continue;
    const auto other_side = std::max_element(groups.begin() + 1, groups.end(), [&](int a, int b) {
      return classification.probability(a, missing) < classification.probability(b, missing);
    });
    if (classification.probability(*other_side, missing) >= kOtherSideProbability ||
        indistinguishable(classification, *other_side, groups.front()))
      classes[*other_side] = missing;
  }
}

// Where pieces are named for: front or back, left or right, each when some of the names say it and
// none says the opposite (expected_region.h reads the names), else Any.
ExpectedRegion named_region(const Garment& garment, const std::vector<int>& pieces) {
  bool front = false, back = false, left = false, right = false;
  for (int piece : pieces) {
    const ExpectedRegion region = expected_region_from_name(garment.pieces[piece].name);
    front = front || region.front_back == FrontBack::Front;
    back = back || region.front_back == FrontBack::Back;
    left = left || region.left_right == LeftRight::Left;
    right = right || region.left_right == LeftRight::Right;
  }
  ExpectedRegion named;
  if (front != back) named.front_back = front ? FrontBack::Front : FrontBack::Back;
  if (left != right) named.left_right = left ? LeftRight::Left : LeftRight::Right;
  return named;
}

// The side each group's names say (Any when they say none), read once per seed choice.
std::vector<FrontBack> named_sides(const Garment& garment,
                                   const PieceClassification& classification) {
  std::vector<FrontBack> sides;
  sides.reserve(classification.groups.size());
  for (const std::vector<int>& group : classification.groups)
    sides.push_back(named_region(garment, group).front_back);
  return sides;
}

// A pattern that names its pieces' sides is believed over the classifier's side, which keeps the
// region (chest or pelvis). The classifier sees shapes and seams only: identical front and back
// panels of a plain skirt get the same probabilities, and the Garment-Pattern-Generator templates,
// unlike the GarmentCode designs it learnt from, fool it outright (their jacket's back comes out a
// front chest with probability 1.000). A back seeded in front mirrors the garment, sleeves and all.
// With the neighbour named for a missing side (complete_from_neighbours), this changes the seed of
// 7 of the 500 GarmentCode designs, all failing before, 4 clean after; of the templates, 3 -> 5
// clean.
// A group the classifier leaves out of the region (class `other`) but gives the region's two sides
// at least kNamedRegionProbability together, named for a side, joins that side: the templates'
// flared trousers have their left front at back pelvis 0.493, other 0.503, and seeded without it
// the trousers' front is one leg.
constexpr double kNamedRegionProbability = 0.3;

void follow_named_sides(const PieceClassification& classification,
                        const std::vector<FrontBack>& sides, GroupClasses& classes, SeedClass front,
                        SeedClass back) {
  for (int g = 0; g < static_cast<int>(classes.size()); ++g) {
    if (sides[g] == FrontBack::Any) continue;
    const bool in_region = classes[g] == front || classes[g] == back;
    const bool nearly_in_region =
        classes[g] == SeedClass::Other &&
        classification.probability(g, front) + classification.probability(g, back) >=
            kNamedRegionProbability;
    if (in_region || nearly_in_region) classes[g] = sides[g] == FrontBack::Front ? front : back;
  }
}

// When the classifier finds one side only (a dress's front chest, its back called a neck piece),
// the other side is the group sewn to it that the classifier ranks highest for the missing class: a
// one-sided seed leaves the other side to the rigid fit of §7.1, which lays it flat beside its
// partner, outside it, instead of round the body (paper §8.3.1: both chest pieces as seeds). The
// classifier must give that group at least kNeighbourSideProbability: a waistband or a hem flap it
// never takes for a side stays out. (The sides it completes on the templates get about 0.33.)
constexpr double kNeighbourSideProbability = 0.1;

void complete_from_neighbours(const Garment& garment, const PieceClassification& classification,
                              const std::vector<FrontBack>& sides, GroupClasses& classes,
                              SeedClass front, SeedClass back) {
  for (const auto& [present, missing] : {std::pair{front, back}, std::pair{back, front}}) {
    const std::vector<int> groups = groups_of_class(classification, classes, present);
    if (groups.empty() || !groups_of_class(classification, classes, missing).empty()) continue;
    const std::vector<int> part =
        connected_groups_of_class(garment, classification, classes, groups.front(), present);
    const FrontBack missing_side = missing == front ? FrontBack::Front : FrontBack::Back;
    const auto named_for_missing = [&](int group) { return sides[group] == missing_side; };
    // A neighbour named for the missing side first, then the classifier's ranking.
    const auto ranks_higher = [&](int a, int b) {
      if (named_for_missing(a) != named_for_missing(b)) return named_for_missing(a);
      return classification.probability(a, missing) > classification.probability(b, missing);
    };
    int best = -1;
    for (const StitchPairs& range : garment.stitches) {
      const Stitch& stitch = garment.pattern.stitches[range.stitch];
      const int a = classification.piece_group[stitch.a.panel],
                b = classification.piece_group[stitch.b.panel];
      for (const auto& [inside, other] : {std::pair{a, b}, std::pair{b, a}}) {
        if (std::find(part.begin(), part.end(), inside) == part.end() || classes[other] == present)
          continue;
        if (best < 0 || ranks_higher(other, best)) best = other;
      }
    }
    if (best >= 0 && (named_for_missing(best) ||
                      classification.probability(best, missing) >= kNeighbourSideProbability))
      classes[best] = missing;
  }
}

// The part of class `wanted` (neck or waist) with the most confident group whose part has a ring
// round the body, as a collar or a waistband does; empty if none. GarmentCode's lapel "collars"
// (two long strips down the front, two flat bands on the shoulders) are classed as neck pieces but
// do not wrap the neck: wrapped round it as a ring, they twist the bodice round it. None of the 32
// such garments of the 500 came out clean from that seed; 10 do from their chest pieces.
std::vector<int> ring_part(const Garment& garment, const PieceClassification& classification,
                           const GroupClasses& classes, SeedClass wanted) {
  for (int group : groups_of_class(classification, classes, wanted)) {
    std::vector<int> pieces = pieces_of(
        classification, connected_groups_of_class(garment, classification, classes, group, wanted));
    if (lay_out_part(garment, pieces).has_ring) return pieces;
  }
  return {};
}

// How far a piece's cloth reaches from its seams with `others` in its rest shape: the largest
// distance from one of its vertices to the nearest of its vertices sewn to them (0 when none is).
double reach_from_seam(const Garment& garment, int piece, const std::vector<int>& others) {
  std::vector<bool> is_other(garment.pieces.size(), false);
  for (int other : others)
    is_other[other] = true;
  std::vector<Eigen::Vector2d> seam;
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k)
    for (int side = 0; side < 2; ++side)
      if (garment.vertex_piece(garment.sewing_pairs(k, side)) == piece &&
          is_other[garment.vertex_piece(garment.sewing_pairs(k, 1 - side))])
        seam.push_back(garment.rest_positions.row(garment.sewing_pairs(k, side)).transpose());
  if (seam.empty()) return 0.0;
  const Piece& info = garment.pieces[piece];
  double reach = 0.0;
  for (int v = info.first_vertex; v < info.first_vertex + info.vertex_count; ++v) {
    const Eigen::Vector2d point = garment.rest_positions.row(v).transpose();
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& seam_point : seam)
      nearest = std::min(nearest, (point - seam_point).norm());
    reach = std::max(reach, nearest);
  }
  return reach;
}

// Whether a band the classifier takes for a waistband is the hem band of a long top instead: a
// chest piece sewn to it reaches more than kHemBandReach times the body's waist-to-neck height up
// from it, so with the band at the waist the top would stand up past the shoulders, its straps
// crumpled round the head. Seeded at the waist, the 9 GarmentCode designs of the 500 whose torso
// pieces reach 0.6 m or more from the band (1.8 to 3.4 times the height) all failed, the 8 beyond
// twice the height with seams open by 5 to 7 cm and strain up to 287 % in the first batch (5) or
// the top crossing itself (3). Seeded at the chest, the band hanging where the top ends, 7 of these
// 8 come out clean, and no other design of the 500 changes seed (gc_0166, at 1.85 times, stays).
constexpr double kHemBandReach = 2.0;

bool is_hem_band(const Garment& garment, const PieceClassification& classification,
                 const GroupClasses& classes, const std::vector<int>& band, double waist_to_neck) {
  if (!(waist_to_neck > 0.0)) return false;
  std::set<int> chest_pieces;
  for (const StitchPairs& range : garment.stitches) {
    const Stitch& stitch = garment.pattern.stitches[range.stitch];
    for (const auto& [inside, other] :
         {std::pair{stitch.a.panel, stitch.b.panel}, std::pair{stitch.b.panel, stitch.a.panel}}) {
      const SeedClass kind = classes[classification.piece_group[other]];
      if (std::find(band.begin(), band.end(), inside) != band.end() &&
          (kind == SeedClass::FrontChest || kind == SeedClass::BackChest))
        chest_pieces.insert(other);
    }
  }
  return std::any_of(chest_pieces.begin(), chest_pieces.end(), [&](int piece) {
    return reach_from_seam(garment, piece, band) > kHemBandReach * waist_to_neck;
  });
}

// The front and back parts of a pair of classes (chest or pelvis), each at its location; empty
// when the classifier finds neither side. A side in two parts not sewn to each other and named for
// the body's left and right (a jacket's open front) is one part, laid out left to right as the
// side is seen from outside: seeded alone, one half would be centred on the location and leave
// the other to be laid flat beside the garment (Garment-Pattern-Generator jackets: 0 -> 1 clean
// of 4; no GarmentCode design has such a part).
std::vector<SeedPart> front_and_back_parts(const Garment& garment,
                                           const PieceClassification& classification,
                                           GroupClasses& classes, SeedClass front, SeedClass back,
                                           const char* front_location, const char* back_location) {
  complete_front_and_back(classification, classes, front, back);
  const std::vector<FrontBack> sides = named_sides(garment, classification);
  follow_named_sides(classification, sides, classes, front, back);
  complete_from_neighbours(garment, classification, sides, classes, front, back);
  std::vector<SeedPart> parts;
  for (const auto& [wanted, location] :
       {std::pair{front, front_location}, std::pair{back, back_location}}) {
    const std::vector<int> groups = groups_of_class(classification, classes, wanted);
    if (groups.empty()) continue;
    const std::vector<int> part =
        connected_groups_of_class(garment, classification, classes, groups.front(), wanted);
    std::vector<int> pieces = pieces_of(classification, part);
    const auto other = std::find_if(groups.begin(), groups.end(), [&](int group) {
      return std::find(part.begin(), part.end(), group) == part.end();
    });
    if (other != groups.end()) {
      std::vector<int> other_pieces =
          pieces_of(classification,
                    connected_groups_of_class(garment, classification, classes, *other, wanted));
      const LeftRight side = named_region(garment, pieces).left_right,
                      other_side = named_region(garment, other_pieces).left_right;
      if (side != LeftRight::Any && other_side != LeftRight::Any && side != other_side) {
        // Seen from the front, the body's right (−x) is on the left; seen from behind, its left.
        const LeftRight first = wanted == front ? LeftRight::Right : LeftRight::Left;
        if (side != first) std::swap(pieces, other_pieces);
        pieces.insert(pieces.end(), other_pieces.begin(), other_pieces.end());
      }
    }
    parts.push_back({pieces, location});
  }
  return parts;
}

}  // namespace

std::vector<int> SeedPlan::pieces() const {
  std::vector<int> all;
  for (const SeedPart& part : parts)
    all.insert(all.end(), part.pieces.begin(), part.pieces.end());
  return all;
}

std::vector<SeedPlan> seed_candidates(const Garment& garment,
                                      const PieceClassification& classification,
                                      double waist_to_neck) {
  std::vector<SeedPlan> plans;
  const auto add = [&](std::vector<SeedPart> parts, std::string reason) {
    for (const SeedPlan& plan : plans)
      if (plan.pieces() == SeedPlan{parts, false, ""}.pieces()) return;
    plans.push_back({std::move(parts), false, std::move(reason)});
  };
  GroupClasses classes = most_probable_classes(classification);
  // 1. The waist piece (a waistband closing round the body). Chest pieces first instead changed
  // the seed of 165 of the 500: 26 came out clean that had not, 25 that had did not.
  // A hem band (is_hem_band) is sewn to chest pieces, so step 2 always takes those instead.
  std::vector<int> waist = ring_part(garment, classification, classes, SeedClass::Waist);
  const bool hem_band =
      !waist.empty() && is_hem_band(garment, classification, classes, waist, waist_to_neck);
  if (!waist.empty() && !hem_band) add({{waist, "waist"}}, "waist piece (classifier)");
  // 2. Front and back chest pieces, before a collar: the paper's own limits (§9) name collars,
  // which fold back over the garment against the rule that every piece faces away from the body;
  // wrapped round the neck as the seed, they twist the bodice they are sewn to. Of the 21
  // garments of the 500 that took a collar ring as their seed, 4 came out clean; 8 do from their
  // chest (or waist) pieces, and none is lost. A manual seed still starts from the collar.
  if (std::vector<SeedPart> chests =
          front_and_back_parts(garment, classification, classes, SeedClass::FrontChest,
                               SeedClass::BackChest, "chest_front", "chest_back");
      !chests.empty())
    add(std::move(chests),
        hem_band ? "chest pieces (classifier; the waist piece is a long top's hem band)"
                 : "chest pieces (classifier)");
  // 3. The neck piece (a collar ring) of a garment without chest pieces.
  if (std::vector<int> neck = ring_part(garment, classification, classes, SeedClass::Neck);
      !neck.empty())
    add({{std::move(neck), "neck"}}, "neck piece (classifier)");
  // 4. Front and back pelvis pieces (skirts and trousers without a waistband).
  if (std::vector<SeedPart> pelvis =
          front_and_back_parts(garment, classification, classes, SeedClass::FrontPelvis,
                               SeedClass::BackPelvis, "pelvis_front", "pelvis_back");
      !pelvis.empty())
    add(std::move(pelvis), "pelvis pieces (classifier)");
  // 5. No seed class found: the group with the most garment below its seams (Eq. 1), at the waist.
  const SewingRelationship relationship(garment);
  int best = 0;
  double best_support = -1.0;
  for (int g = 0; g < static_cast<int>(classification.groups.size()); ++g) {
    const std::vector<bool> from = relationship.mask(classification.groups[g]);
    double support = 0.0;
    for (int p = 0; p < relationship.piece_count(); ++p)
      if (!from[p]) support += relationship.score(from, p);
    if (support > best_support) {
      best_support = support;
      best = g;
    }
  }
  add({{classification.groups[best], "waist"}}, "rule: most garment hanging below its seams");
  return plans;
}

SeedPlan choose_seed(const Garment& garment, const PieceClassification& classification,
                     double waist_to_neck) {
  return seed_candidates(garment, classification, waist_to_neck).front();
}

SeedPlan manual_seed(const Garment& garment, const std::vector<std::string>& piece_names,
                     const std::string& location, const std::vector<std::string>& known_locations) {
  if (piece_names.empty()) throw InputError("seed: no seed pieces given");
  if (std::find(known_locations.begin(), known_locations.end(), location) ==
      known_locations.end()) {
    std::string list;
    for (const std::string& name : known_locations)
      list += (list.empty() ? "" : ", ") + name;
    throw InputError("seed: unknown body location '" + location + "' (known: " + list + ")");
  }
  SeedPlan plan;
  plan.manual = true;
  plan.reason = "manual";
  SeedPart part;
  part.location = location;
  for (const std::string& name : piece_names) {
    const int piece = garment.pattern.panel_index(name);
    if (piece < 0)
      throw InputError(garment.pattern.source + ": seed: no panel named '" + name + "'");
    if (std::find(part.pieces.begin(), part.pieces.end(), piece) == part.pieces.end())
      part.pieces.push_back(piece);
  }
  plan.parts.push_back(part);
  return plan;
}

}  // namespace garment
