#include "engine/pattern/flat_regions.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <string>

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
    for (int member : members)
      edge_to[member].assign(pattern.panels[member].edges.size(), EdgeRef{index, -1});
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
