#include "engine/pattern/flat_regions.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <string>
#include <utility>

#include "engine/core/error.h"
#include "engine/pattern/edge_curve.h"
#include "engine/pattern/outfit.h"

namespace garment {
namespace {

// Points closer than this (metres) are one point: quilting writes the two sides of a cut from the
// same numbers, and GarmentCode's torso halves share their centre line exactly.
constexpr double kSamePoint = 1e-5;

bool same_frame(const Panel& a, const Panel& b) {
  return (a.rotation_degrees - b.rotation_degrees).cwiseAbs().maxCoeff() < 1e-9 &&
         (a.translation - b.translation).cwiseAbs().maxCoeff() < 1e-9;
}

bool same_point(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - b).norm() < kSamePoint;
}

bool sewn_flat(const Pattern& pattern, const Stitch& stitch) {
  if (stitch.is_dart() || stitch.right_wrong) return false;
  const Panel& a = pattern.panels[stitch.a.panel];
  const Panel& b = pattern.panels[stitch.b.panel];
  if (!same_frame(a, b)) return false;
  const PanelEdge& edge_a = a.edges[stitch.a.edge];
  const PanelEdge& edge_b = b.edges[stitch.b.edge];
  return same_point(a.vertices[edge_a.start], b.vertices[edge_b.end]) &&
         same_point(a.vertices[edge_a.end], b.vertices[edge_b.start]) &&
         same_point(EdgeCurve(a, edge_a).point(0.5), EdgeCurve(b, edge_b).point(0.5));
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

// The words of the first piece's name that every piece's name has, joined by '_'.
std::string shared_name(const Pattern& pattern, const std::vector<int>& members) {
  std::string name;
  for (const std::string_view word : panel_name_words(pattern.panels[members.front()].name)) {
    const bool everywhere = std::all_of(members.begin(), members.end(), [&](int member) {
      const std::vector<std::string_view> words = panel_name_words(pattern.panels[member].name);
      return std::find(words.begin(), words.end(), word) != words.end();
    });
    if (everywhere) (name += name.empty() ? "" : "_") += word;
  }
  return name.empty() ? pattern.panels[members.front()].name : name;
}

// A region's outline: its edges not sewn flat, chained end to start into one loop, first edge
// first; empty when they branch or make more than one loop.
std::vector<EdgeRef> outline_loop(const Pattern& pattern, const std::vector<int>& members,
                                  const std::set<std::pair<int, int>>& flat_edges) {
  std::vector<EdgeRef> boundary;
  for (int member : members)
    for (std::size_t e = 0; e < pattern.panels[member].edges.size(); ++e)
      if (!flat_edges.count({member, static_cast<int>(e)}))
        boundary.push_back({member, static_cast<int>(e)});
  auto point = [&](const EdgeRef& ref, bool end) -> const Eigen::Vector2d& {
    const Panel& panel = pattern.panels[ref.panel];
    const PanelEdge& edge = panel.edges[ref.edge];
    return panel.vertices[end ? edge.end : edge.start];
  };
  std::vector<EdgeRef> loop;
  std::vector<bool> used(boundary.size(), false);
  if (boundary.empty()) return loop;
  std::size_t current = 0;
  while (!used[current]) {
    used[current] = true;
    loop.push_back(boundary[current]);
    int next = -1;
    for (std::size_t j = 0; j < boundary.size(); ++j) {
      if (!same_point(point(boundary[current], true), point(boundary[j], false))) continue;
      if (next >= 0) return {};  // two edges start where this one ends
      next = static_cast<int>(j);
    }
    if (next < 0) return {};
    current = static_cast<std::size_t>(next);
  }
  if (current != 0 || loop.size() != boundary.size()) return {};
  return loop;
}

// Whether every point of `curve` lies on `a` or `b` and the middles of both on `curve`, within
// the dense polylines' accuracy: `curve` is the two of them as one.
bool is_union(const Panel& panel, const PanelEdge& curve, const PanelEdge& a, const PanelEdge& b) {
  // Metres: the dense polylines follow the curves to a fraction of a millimetre.
  constexpr double kOnCurve = 2e-4;
  const EdgeCurve joined(panel, curve), first(panel, a), second(panel, b);
  auto near = [&](const Eigen::Vector2d& point, const EdgeCurve& on) {
    return on.distance_to(point) < kOnCurve;
  };
  for (int k = 1; k < 16; ++k) {
    const Eigen::Vector2d point = joined.point(k / 16.0);
    if (!near(point, first) && !near(point, second)) return false;
  }
  return near(first.point(0.5), joined) && near(second.point(0.5), joined);
}

// Edges a (…→P) and b (P→…) of `panel` as one curve of their kind, when they are parts of one (a
// straight line, an arc, a Bézier curve cut at P); nullopt otherwise.
std::optional<PanelEdge> joined_edge(const Panel& panel, const PanelEdge& a, const PanelEdge& b) {
  if (a.kind != b.kind || a.label != b.label) return std::nullopt;
  PanelEdge joined = a;
  joined.end = b.end;
  const Eigen::Vector2d& split = panel.vertices[a.end];
  std::vector<PanelEdge> candidates;
  switch (a.kind) {
    case CurveKind::Straight:
      candidates.push_back(joined);
      break;
    case CurveKind::Circle:
      if (std::abs(a.radius - b.radius) > kSamePoint || a.right != b.right) return std::nullopt;
      for (bool large : {false, true}) {
        joined.large_arc = large;
        candidates.push_back(joined);
      }
      break;
    case CurveKind::Quadratic:
    case CurveKind::Cubic: {
      // Cut at t, the control points next to P split the tangent there as t to 1 - t.
      const Eigen::Vector2d& before = a.controls.back();
      const Eigen::Vector2d& after = b.controls.front();
      const double t = (split - before).norm() / ((split - before).norm() + (after - split).norm());
      if (!(t > 0.0 && t < 1.0)) return std::nullopt;
      const Eigen::Vector2d& start = panel.vertices[a.start];
      const Eigen::Vector2d& end = panel.vertices[b.end];
      if (a.kind == CurveKind::Quadratic) {
        joined.controls = {start + (a.controls[0] - start) / t};
      } else {
        joined.controls = {start + (a.controls[0] - start) / t,
                           end + (b.controls[1] - end) / (1.0 - t)};
      }
      candidates.push_back(joined);
      break;
    }
  }
  for (const PanelEdge& candidate : candidates)
    if (is_union(panel, candidate, a, b)) return candidate;
  return std::nullopt;
}

// Replaces edges `first` and the one after it of `panel` by `joined` (the vertex between them
// goes); stitches on the panel are re-addressed, those on the edge after `first` to `joined`.
void join_at(Pattern& pattern, int panel_index, int first, const PanelEdge& joined) {
  Panel& panel = pattern.panels[panel_index];
  const int count = static_cast<int>(panel.edges.size());
  const int gone = (first + 1) % count;
  panel.edges[first] = joined;
  panel.edges.erase(panel.edges.begin() + gone);
  panel.vertices.erase(panel.vertices.begin() + gone);
  const int kept = first > gone ? first - 1 : first;
  for (std::size_t e = 0; e < panel.edges.size(); ++e) {
    panel.edges[e].start = static_cast<int>(e);
    panel.edges[e].end = static_cast<int>((e + 1) % panel.edges.size());
  }
  auto readdress = [&](EdgeRef& ref) {
    if (ref.panel != panel_index) return;
    ref.edge = ref.edge == gone ? kept : ref.edge > gone ? ref.edge - 1 : ref.edge;
  };
  for (Stitch& stitch : pattern.stitches) {
    readdress(stitch.a);
    readdress(stitch.b);
  }
}

// The stitch side on (panel, edge): (stitch index, true for side a); (-1, false) when free.
std::pair<int, bool> stitch_on(const Pattern& pattern, int panel, int edge) {
  for (std::size_t s = 0; s < pattern.stitches.size(); ++s) {
    const Stitch& stitch = pattern.stitches[s];
    if (stitch.a.panel == panel && stitch.a.edge == edge) return {static_cast<int>(s), true};
    if (stitch.b.panel == panel && stitch.b.edge == edge) return {static_cast<int>(s), false};
  }
  return {-1, false};
}

// Where a cut met a merged panel's outline, its two sides are joined back into the edge the
// quilting cut, when they are parts of one curve and either both free or both sewn to the two
// parts of one edge elsewhere (joined there too, the two stitches becoming one): a region is then
// the panel it was cut from, and meshes as it does.
void join_cut_edges(Pattern& pattern, const std::vector<std::vector<Eigen::Vector2d>>& cut_ends) {
  for (bool joined = true; joined;) {
    joined = false;
    for (std::size_t p = 0; p < pattern.panels.size() && !joined; ++p) {
      const int panel = static_cast<int>(p);
      for (const Eigen::Vector2d& end : cut_ends[p]) {
        const Panel& outline = pattern.panels[p];
        const int count = static_cast<int>(outline.edges.size());
        int at = -1;  // the vertex
        for (int v = 0; v < count && at < 0; ++v)
          if (same_point(outline.vertices[v], end)) at = v;
        if (at < 0 || count < 3) continue;
        const int first = (at + count - 1) % count;
        const std::optional<PanelEdge> whole =
            joined_edge(outline, outline.edges[first], outline.edges[at]);
        if (!whole) continue;
        const auto [stitch_a, side_a] = stitch_on(pattern, panel, first);
        const auto [stitch_b, side_b] = stitch_on(pattern, panel, at);
        if (stitch_a < 0 && stitch_b < 0) {
          join_at(pattern, panel, first, *whole);
          joined = true;
          break;
        }
        if (stitch_a < 0 || stitch_b < 0 || stitch_a == stitch_b) continue;
        const Stitch& sa = pattern.stitches[stitch_a];
        const Stitch& sb = pattern.stitches[stitch_b];
        const EdgeRef other_a = side_a ? sa.b : sa.a;
        const EdgeRef other_b = side_b ? sb.b : sb.a;
        if (sa.right_wrong != sb.right_wrong || other_a.panel != other_b.panel ||
            other_a.panel == panel)
          continue;
        // The other side runs the other way (a stitch pairs a.start with b.end) unless right_wrong.
        const Panel& partner = pattern.panels[other_a.panel];
        const int partner_count = static_cast<int>(partner.edges.size());
        const int partner_first = sa.right_wrong ? other_a.edge : other_b.edge;
        const int partner_second = sa.right_wrong ? other_b.edge : other_a.edge;
        if ((partner_first + 1) % partner_count != partner_second || partner_count < 3) continue;
        const std::optional<PanelEdge> partner_whole =
            joined_edge(partner, partner.edges[partner_first], partner.edges[partner_second]);
        if (!partner_whole) continue;
        // One stitch for both parts: the first one's, the second one dropped.
        const int partner_panel = other_a.panel;
        pattern.stitches.erase(pattern.stitches.begin() + stitch_b);
        join_at(pattern, panel, first, *whole);
        join_at(pattern, partner_panel, partner_first, *partner_whole);
        joined = true;
        break;
      }
    }
  }
}

}  // namespace

std::vector<bool> stitches_sewn_flat(const Pattern& pattern) {
  std::vector<bool> flat(pattern.stitches.size());
  for (std::size_t s = 0; s < pattern.stitches.size(); ++s)
    flat[s] = sewn_flat(pattern, pattern.stitches[s]);
  return flat;
}

std::optional<RegionPattern> merge_flat_regions(const Pattern& pattern) {
  const int panels = static_cast<int>(pattern.panels.size());
  const std::vector<bool> flat = stitches_sewn_flat(pattern);
  std::vector<int> parent(panels);
  std::iota(parent.begin(), parent.end(), 0);
  std::set<std::pair<int, int>> flat_edges;
  for (std::size_t s = 0; s < pattern.stitches.size(); ++s) {
    if (!flat[s]) continue;
    const Stitch& stitch = pattern.stitches[s];
    flat_edges.insert({stitch.a.panel, stitch.a.edge});
    flat_edges.insert({stitch.b.panel, stitch.b.edge});
    parent[find_root(parent, stitch.a.panel)] = find_root(parent, stitch.b.panel);
  }
  // Regions in the order of their first panel.
  std::vector<std::vector<int>> regions;
  std::vector<int> region_of_root(panels, -1);
  for (int p = 0; p < panels; ++p) {
    int& region = region_of_root[find_root(parent, p)];
    if (region < 0) {
      region = static_cast<int>(regions.size());
      regions.emplace_back();
    }
    regions[region].push_back(p);
  }
  if (std::none_of(regions.begin(), regions.end(),
                   [](const std::vector<int>& members) { return members.size() > 2; }))
    return std::nullopt;

  RegionPattern result;
  result.pattern.source = pattern.source;
  result.pattern.units_in_meter = pattern.units_in_meter;
  result.region_of_panel.assign(panels, -1);
  // Where each original edge went: (merged panel, edge).
  std::vector<std::vector<EdgeRef>> edge_to(panels);
  std::set<std::string> names;
  std::vector<bool> merged_panel;  // per output panel: a region merged into one
  // Per output panel: where the cuts met its outline (the ends of the edges sewn flat).
  std::vector<std::vector<Eigen::Vector2d>> cut_ends;
  bool any_merged = false;
  auto add_panel = [&](Panel panel, const std::vector<int>& members) {
    std::string name = panel.name;
    for (int suffix = 2; !names.insert(name).second; ++suffix)
      name = panel.name + "_" + std::to_string(suffix);
    panel.name = name;
    const int index = static_cast<int>(result.pattern.panels.size());
    for (int member : members)
      result.region_of_panel[member] = index;
    result.pattern.panels.push_back(std::move(panel));
    merged_panel.push_back(members.size() > 1);
    result.pieces_of_region.push_back(static_cast<int>(members.size()));
    return index;
  };
  for (const std::vector<int>& members : regions) {
    const std::vector<EdgeRef> loop =
        members.size() > 1 ? outline_loop(pattern, members, flat_edges) : std::vector<EdgeRef>();
    if (loop.empty()) {  // a piece alone, or a region with a hole: its pieces stay as they are
      for (int member : members) {
        const int index = add_panel(pattern.panels[member], {member});
        for (std::size_t e = 0; e < pattern.panels[member].edges.size(); ++e)
          edge_to[member].push_back({index, static_cast<int>(e)});
      }
      continue;
    }
    any_merged = true;
    const Panel& first = pattern.panels[members.front()];
    Panel merged;
    merged.name = shared_name(pattern, members);
    merged.rotation_degrees = first.rotation_degrees;
    merged.translation = first.translation;
    merged.label = first.label;
    const int count = static_cast<int>(loop.size());
    const int index = static_cast<int>(result.pattern.panels.size());
    for (int i = 0; i < count; ++i) {
      const Panel& piece = pattern.panels[loop[i].panel];
      PanelEdge edge = piece.edges[loop[i].edge];
      merged.vertices.push_back(piece.vertices[edge.start]);
      edge.start = i;
      edge.end = (i + 1) % count;
      merged.edges.push_back(std::move(edge));
    }
    std::vector<Eigen::Vector2d> ends;
    for (int member : members) {
      edge_to[member].assign(pattern.panels[member].edges.size(), EdgeRef{index, -1});
      const Panel& piece = pattern.panels[member];
      for (std::size_t e = 0; e < piece.edges.size(); ++e)
        if (flat_edges.count({member, static_cast<int>(e)}))
          ends.insert(ends.end(),
                      {piece.vertices[piece.edges[e].start], piece.vertices[piece.edges[e].end]});
    }
    cut_ends.resize(index + 1);
    cut_ends[index] = std::move(ends);
    for (int i = 0; i < count; ++i)
      edge_to[loop[i].panel][loop[i].edge].edge = i;
    add_panel(std::move(merged), members);
  }
  for (std::size_t s = 0; s < pattern.stitches.size(); ++s) {
    if (flat[s] && merged_panel[result.region_of_panel[pattern.stitches[s].a.panel]]) continue;
    Stitch stitch = pattern.stitches[s];
    stitch.a = edge_to[stitch.a.panel][stitch.a.edge];
    stitch.b = edge_to[stitch.b.panel][stitch.b.edge];
    result.pattern.stitches.push_back(stitch);
  }
  if (!any_merged) return std::nullopt;
  cut_ends.resize(result.pattern.panels.size());
  join_cut_edges(result.pattern, cut_ends);
  return result;
}

std::optional<MeshedRegions> mesh_flat_regions(const Pattern& pattern,
                                               const MeshingOptions& options) {
  std::optional<RegionPattern> regions = merge_flat_regions(pattern);
  if (!regions) return std::nullopt;
  MeshingOptions coarse = options;
  coarse.target_edge_length =
      std::max(options.target_edge_length, MeshingOptions().target_edge_length);
  try {
    return MeshedRegions{build_garment(regions->pattern, coarse),
                         std::move(regions->region_of_panel), std::move(regions->pieces_of_region)};
  } catch (const BudgetError&) {
    throw;
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace garment
