#include "engine/pattern/quilting.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

#include "engine/core/error.h"
#include "engine/pattern/edge_curve.h"
#include "engine/pattern/outline.h"

namespace garment {
namespace {
// Named as well, so that in a unity build these helpers do not meet other files' ones.
namespace quilting {

using Json = nlohmann::json;
using Eigen::Vector2d;

// Curved edges are flattened to chords this long (as EdgeCurve's dense polyline): the cut points
// then lie within a few micrometres of the curve.
constexpr double kFlatteningStep = 0.001;  // metres
constexpr int kMinCurveSegments = 16, kMaxCurveSegments = 1024;

// A grid line may move by up to 3/10 of a cell from its regular place, to the position (in steps
// of 1/10) whose smallest piece is largest: a line through a corner or grazing a curve would
// otherwise leave a sliver that meshes badly.
constexpr int kLineShifts[] = {0, 1, -1, 2, -2, 3, -3};
constexpr double kShiftStep = 0.1;           // of a cell
constexpr double kGoodSmallestPiece = 0.25;  // of a cell's area: stop looking for a better place

// Lines are kept off the vertices by this much, so that every crossing splits a segment inside.
constexpr double kLineClearance = 1e-7;  // metres
// A line is placed this far from the corners of the pieces it cuts (original vertices, ends of
// earlier cuts) when one of its places allows: nearer, it leaves an edge shorter than this beside
// the corner, or runs along an edge parallel to it, a sliver thinner than this.
constexpr double kCornerClearance = 0.004;  // metres, at most kCornerClearanceOfCell of a cell
constexpr double kCornerClearanceOfCell = 0.04;

// A piece smaller than this (of a cell's area) joins the neighbour it shares the longest cut
// with: the mesher cannot shape a piece a few centimetres round (it refuses it), and a sliver
// carries no cloth.
constexpr double kSmallestPiece = 0.1;

// Where two sides of a stitch were cut within this length of each other, one vertex serves both
// (the stitch pairs them), rather than two vertices a sliver apart.
constexpr double kStitchMergeLength = 0.003;  // metres

// Grid lines per panel and direction: past this the cell is not a cell but a typo.
constexpr int kMaxLinesPerAxis = 1000;

// The part of a piece's outline from point i to point i+1: a stretch of an original edge between
// two arc lengths, or a stretch of a cut.
struct Segment {
  int edge = -1;  // original edge, or -1 on a cut
  int cut = -1;   // the cut line when edge == -1
  double s0 = 0.0, s1 = 0.0;
};

struct Piece {
  std::vector<Vector2d> points;
  std::vector<Segment> segments;  // segments[i] runs from points[i] to points[i + 1 (mod n)]
  int row = 0, column = 0;
};

// One original edge as chords at uniform curve parameter, with the arc length at each sample.
struct SampledEdge {
  std::vector<double> u, s;
  std::vector<Vector2d> points;
  double length() const { return s.back(); }
  double parameter_at(double arc_length) const {
    if (arc_length <= 0.0) return 0.0;
    if (arc_length >= length()) return 1.0;
    const auto upper = std::upper_bound(s.begin(), s.end(), arc_length);
    const std::size_t i = static_cast<std::size_t>(upper - s.begin());
    const double span = s[i] - s[i - 1];
    const double fraction = span > 0.0 ? (arc_length - s[i - 1]) / span : 0.0;
    return u[i - 1] + fraction * (u[i] - u[i - 1]);
  }
};

SampledEdge sample_edge(const Panel& panel, const PanelEdge& edge) {
  const EdgeCurve curve(panel, edge);
  const int segments =
      edge.kind == CurveKind::Straight
          ? 1
          : std::clamp(static_cast<int>(std::ceil(curve.length() / kFlatteningStep)),
                       kMinCurveSegments, kMaxCurveSegments);
  SampledEdge sampled;
  for (int i = 0; i <= segments; ++i) {
    const double u = static_cast<double>(i) / segments;
    sampled.u.push_back(u);
    sampled.points.push_back(i == 0          ? panel.vertices[edge.start]
                             : i == segments ? panel.vertices[edge.end]
                                             : curve.point(u));
    sampled.s.push_back(
        i == 0 ? 0.0 : sampled.s.back() + (sampled.points[i] - sampled.points[i - 1]).norm());
  }
  return sampled;
}

Piece flatten(const std::vector<SampledEdge>& edges) {
  Piece piece;
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (std::size_t i = 0; i + 1 < edges[e].points.size(); ++i) {
      piece.points.push_back(edges[e].points[i]);
      piece.segments.push_back({static_cast<int>(e), -1, edges[e].s[i], edges[e].s[i + 1]});
    }
  return piece;
}

// The point where segment p–q crosses coordinate `axis` = c, computed from the endpoints in a fixed
// order so that the two pieces sharing a cut get the very same point.
Vector2d crossing_point(Vector2d p, Vector2d q, int axis, double c) {
  if (q[axis] < p[axis]) std::swap(p, q);
  const double t = (c - p[axis]) / (q[axis] - p[axis]);
  Vector2d x = p + t * (q - p);
  x[axis] = c;
  return x;
}

// Splits a simple polygon by the line `axis` = c (no point on it). Along a line, the crossings of a
// simple outline alternate in and out, so sorted along the line they pair up into the cuts; each
// part is then walked along the outline, jumping across the cut at every crossing it reaches.
// Returns nothing when the crossings do not pair up (the outline touches itself).
std::optional<std::vector<Piece>> split(const Piece& piece, int axis, double c, int cut_id) {
  struct Node {
    Vector2d point;
    Segment out;
    bool crossing = false;
    int partner = -1;
  };
  const std::size_t n = piece.points.size();
  std::vector<Node> nodes;
  nodes.reserve(n + 8);
  for (std::size_t i = 0; i < n; ++i) {
    const Vector2d& p = piece.points[i];
    const Vector2d& q = piece.points[(i + 1) % n];
    const Segment& segment = piece.segments[i];
    nodes.push_back({p, segment});
    if ((p[axis] < c) == (q[axis] < c)) continue;
    const Vector2d x = crossing_point(p, q, axis, c);
    const double t = (x - p).norm() / std::max((q - p).norm(), 1e-300);
    Segment first = segment, second = segment;
    if (segment.edge >= 0) first.s1 = second.s0 = segment.s0 + t * (segment.s1 - segment.s0);
    nodes.back().out = first;
    nodes.push_back({x, second, true});
  }
  std::vector<int> crossings;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].crossing) crossings.push_back(static_cast<int>(i));
  if (crossings.empty()) {
    Piece same = piece;
    if (piece.points[0][axis] > c) (axis == 0 ? same.column : same.row) += 1;
    return std::vector<Piece>{same};
  }
  if (crossings.size() % 2 != 0) return std::nullopt;
  std::sort(crossings.begin(), crossings.end(),
            [&](int a, int b) { return nodes[a].point[1 - axis] < nodes[b].point[1 - axis]; });
  for (std::size_t k = 0; k < crossings.size(); k += 2) {
    nodes[crossings[k]].partner = crossings[k + 1];
    nodes[crossings[k + 1]].partner = crossings[k];
  }
  const int m = static_cast<int>(nodes.size());
  std::vector<bool> visited(nodes.size(), false);
  std::vector<Piece> parts;
  for (int start = 0; start < m; ++start) {
    if (nodes[start].crossing || visited[start]) continue;
    Piece part;
    part.row = piece.row;
    part.column = piece.column;
    if (nodes[start].point[axis] > c) (axis == 0 ? part.column : part.row) += 1;
    int i = start, steps = 0;
    do {
      if (++steps > 2 * m) return std::nullopt;
      visited[i] = true;
      part.points.push_back(nodes[i].point);
      part.segments.push_back(nodes[i].out);
      const int next = (i + 1) % m;
      if (nodes[next].crossing) {
        part.points.push_back(nodes[next].point);
        part.segments.push_back({-1, cut_id, 0.0, 0.0});
        i = nodes[next].partner;
      } else {
        i = next;
      }
    } while (i != start);
    parts.push_back(std::move(part));
  }
  return parts;
}

// Cuts every piece by the grid lines of one direction, each line placed (see kLineShifts) where
// its smallest new piece is largest.
std::vector<Piece> cut_along(std::vector<Piece> pieces, int axis, double cell, int& next_cut_id,
                             const std::string& place, const std::string& source) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Piece& piece : pieces)
    for (const Vector2d& p : piece.points) {
      lo = std::min(lo, p[axis]);
      hi = std::max(hi, p[axis]);
    }
  const double extent = hi - lo;
  const double count = std::ceil(extent / cell - 1e-9);
  if (count > kMaxLinesPerAxis)
    throw_input_error(source, place,
                      "a cell of " + std::to_string(cell) + " m cuts it into more than " +
                          std::to_string(kMaxLinesPerAxis) + " strips");
  const int lines = static_cast<int>(count) - 1;
  const double first = 0.5 * (lo + hi) - 0.5 * count * cell;  // the grid centred on the panel
  const double clearance = std::min(kCornerClearance, kCornerClearanceOfCell * cell);
  for (int k = 1; k <= lines; ++k) {
    const int cut_id = next_cut_id++;
    std::vector<double> corners;  // coordinates along `axis`
    for (const Piece& piece : pieces) {
      const std::size_t n = piece.segments.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Segment& before = piece.segments[(i + n - 1) % n];
        if (before.edge != piece.segments[i].edge || before.cut != piece.segments[i].cut)
          corners.push_back(piece.points[i][axis]);
      }
    }
    std::optional<std::vector<Piece>> best;
    std::pair<bool, double> best_score{false, -1.0};  // clear of corners, smallest new piece
    for (int shift : kLineShifts) {
      double c = first + (k + kShiftStep * shift) * cell;
      for (int tries = 0; tries < 100; ++tries) {
        bool clear = true;
        for (const Piece& piece : pieces)
          for (const Vector2d& p : piece.points)
            if (std::abs(p[axis] - c) < kLineClearance) clear = false;
        if (clear) break;
        c += 3.0 * kLineClearance;
      }
      std::vector<Piece> result;
      double smallest = std::numeric_limits<double>::infinity();
      bool paired = true;
      for (const Piece& piece : pieces) {
        auto parts = split(piece, axis, c, cut_id);
        if (!parts) {
          paired = false;
          break;
        }
        if (parts->size() > 1)
          for (const Piece& part : *parts)
            smallest = std::min(smallest, std::abs(polygon_signed_area(part.points)));
        for (Piece& part : *parts)
          result.push_back(std::move(part));
      }
      if (!paired) continue;
      const bool clear = std::none_of(corners.begin(), corners.end(), [&](double corner) {
        return std::abs(corner - c) < clearance;
      });
      const std::pair<bool, double> score{clear, smallest};
      if (!best || score > best_score) {
        best_score = score;
        best = std::move(result);
      }
      if (best_score.first && best_score.second >= kGoodSmallestPiece * cell * cell) break;
    }
    if (!best)
      throw_input_error(source, place,
                        "cannot be cut: its outline touches itself where a grid line crosses it");
    pieces = std::move(*best);
  }
  return pieces;
}

// Joins piece `small` to `other` across their shared cut segment (small's segment i is other's
// segment j reversed), and folds away the spikes left where more of that cut was shared. Returns
// nothing when the two still touch elsewhere (the union would hold a slit or a hole).
std::optional<Piece> joined(const Piece& small, std::size_t i, const Piece& other, std::size_t j) {
  Piece result;
  result.row = other.row;
  result.column = other.column;
  for (const auto& [piece, shared] : {std::pair{&small, i}, std::pair{&other, j}}) {
    const std::size_t n = piece->points.size();
    for (std::size_t k = 1; k < n; ++k) {
      result.points.push_back(piece->points[(shared + k) % n]);
      result.segments.push_back(piece->segments[(shared + k) % n]);
    }
  }
  for (bool folded = true; folded && result.points.size() > 3;) {
    folded = false;
    const std::size_t n = result.points.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t before = (k + n - 1) % n, after = (k + 1) % n;
      if (result.points[before] != result.points[after]) continue;
      // before → k → after is a spike: there and back along a cut both pieces shared.
      result.segments[before] = result.segments[after];
      const std::size_t first = std::min(k, after), second = std::max(k, after);
      result.points.erase(result.points.begin() + second);
      result.segments.erase(result.segments.begin() + second);
      result.points.erase(result.points.begin() + first);
      result.segments.erase(result.segments.begin() + first);
      folded = true;
      break;
    }
  }
  std::map<std::pair<std::array<double, 2>, std::array<double, 2>>, int> cuts;
  const std::size_t n = result.points.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (result.segments[k].edge >= 0) continue;
    std::array<double, 2> from{result.points[k].x(), result.points[k].y()};
    std::array<double, 2> to{result.points[(k + 1) % n].x(), result.points[(k + 1) % n].y()};
    if (to < from) std::swap(from, to);
    if (++cuts[{from, to}] > 1) return std::nullopt;
  }
  return result;
}

// Merges every piece smaller than `smallest` (m²) into the neighbour it shares the longest cut
// segment with, smallest first.
void merge_small_pieces(std::vector<Piece>& pieces, double smallest) {
  std::vector<std::size_t> refused;  // pieces no neighbour could take
  while (pieces.size() > 1) {
    std::optional<std::size_t> small;
    double small_area = smallest;
    for (std::size_t a = 0; a < pieces.size(); ++a) {
      const double area = std::abs(polygon_signed_area(pieces[a].points));
      if (area < small_area && std::find(refused.begin(), refused.end(), a) == refused.end()) {
        small = a;
        small_area = area;
      }
    }
    if (!small) return;
    const Piece& piece = pieces[*small];
    const std::size_t n = piece.points.size();
    std::optional<Piece> best;
    std::size_t best_other = 0;
    double best_length = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (piece.segments[i].edge >= 0) continue;
      const Vector2d& p = piece.points[i];
      const Vector2d& q = piece.points[(i + 1) % n];
      if ((q - p).norm() <= best_length) continue;
      for (std::size_t b = 0; b < pieces.size(); ++b) {
        if (b == *small) continue;
        const std::size_t m = pieces[b].points.size();
        for (std::size_t j = 0; j < m; ++j)
          if (pieces[b].segments[j].edge < 0 && pieces[b].points[j] == q &&
              pieces[b].points[(j + 1) % m] == p) {
            if (auto union_piece = joined(piece, i, pieces[b], j)) {
              best = std::move(union_piece);
              best_other = b;
              best_length = (q - p).norm();
            }
          }
      }
    }
    if (!best) {
      refused.push_back(*small);
      continue;
    }
    pieces[best_other] = std::move(*best);
    pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(*small));
    for (std::size_t& r : refused)
      if (r > *small) --r;
  }
}

// A maximal stretch of a piece's outline along one original edge or one cut.
struct Run {
  int edge = -1, cut = -1;
  Vector2d start, end;
  double s0 = 0.0, s1 = 0.0;  // arc lengths on the original edge
};

std::vector<Run> runs_of(const Piece& piece) {
  const std::size_t n = piece.segments.size();
  // Each cut segment is a run of its own: after merge_small_pieces two segments of one cut line
  // may follow each other, each sewn to another neighbour.
  const auto same_source = [&](std::size_t a, std::size_t b) {
    return piece.segments[a].edge >= 0 && piece.segments[a].edge == piece.segments[b].edge;
  };
  std::size_t first = 0;
  while (first < n && same_source(first, (first + n - 1) % n))
    ++first;
  std::vector<Run> runs;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (first + k) % n;
    const Segment& segment = piece.segments[i];
    if (k == 0 || !same_source(i, (i + n - 1) % n))
      runs.push_back({segment.edge, segment.cut, piece.points[i], piece.points[(i + 1) % n],
                      segment.s0, segment.s1});
    runs.back().end = piece.points[(i + 1) % n];
    runs.back().s1 = segment.s1;
  }
  return runs;
}

// Control polygon of the part [a, b] of a Bézier curve (de Casteljau twice).
std::vector<Vector2d> bezier_part(std::vector<Vector2d> control, double a, double b) {
  const auto split_at = [](std::vector<Vector2d> points, double t, bool keep_left) {
    std::vector<Vector2d> left{points.front()}, right{points.back()};
    while (points.size() > 1) {
      for (std::size_t i = 0; i + 1 < points.size(); ++i)
        points[i] = (1.0 - t) * points[i] + t * points[i + 1];
      points.pop_back();
      left.push_back(points.front());
      right.push_back(points.back());
    }
    std::reverse(right.begin(), right.end());
    return keep_left ? left : right;
  };
  control = split_at(std::move(control), b, true);
  return split_at(std::move(control), b > 0.0 ? a / b : 0.0, false);
}

// Writes the curvature of the part [u0, u1] of `edge`, between the file points p0 and p1.
Json curvature_of_part(const Panel& panel, const PanelEdge& edge, double u0, double u1,
                       const Vector2d& p0, const Vector2d& p1, double units) {
  if (edge.kind == CurveKind::Straight) return nullptr;
  if (edge.kind == CurveKind::Circle) {
    // The same circle: radius as EdgeCurve takes it (at least half the chord), sweep in proportion.
    const double chord = (panel.vertices[edge.end] - panel.vertices[edge.start]).norm();
    const double radius = std::max(edge.radius, 0.5 * chord);
    const double minor = 2.0 * std::asin(std::min(1.0, chord / (2.0 * radius)));
    const double sweep = (edge.large_arc ? 2.0 * std::numbers::pi - minor : minor) * (u1 - u0);
    return {{"type", "circle"},
            {"params", {radius * units, sweep > std::numbers::pi ? 1 : 0, edge.right ? 1 : 0}}};
  }
  std::vector<Vector2d> control{panel.vertices[edge.start]};
  for (const Vector2d& c : edge.controls)
    control.push_back(c);
  control.push_back(panel.vertices[edge.end]);
  control = bezier_part(control, u0, u1);
  const Vector2d chord = p1 - p0;
  const Vector2d normal(-chord.y(), chord.x());
  const double squared = chord.squaredNorm();
  Json params = Json::array();
  for (std::size_t i = 1; i + 1 < control.size(); ++i) {
    const Vector2d d = control[i] - p0;
    params.push_back({d.dot(chord) / squared, d.dot(normal) / squared});
  }
  return {{"type", edge.kind == CurveKind::Quadratic ? "quadratic" : "cubic"}, {"params", params}};
}

// Where an original edge is divided into output edges: fractions of its length, 0 and 1 included.
using Divisions = std::vector<double>;

// The divisions of a stitch's two sides, made to correspond: A's k-th part is sewn to B's k-th
// (right_wrong) or B's k-th from the end (default, reversed pairing).
void match_divisions(Divisions& a, Divisions& b, bool right_wrong, double length_a,
                     double length_b) {
  struct Item {
    double key;  // position along A
    double value;
    bool on_a;
  };
  // The ends pair with the ends whatever lies near them; only inner divisions are matched.
  std::vector<Item> items;
  for (double f : a)
    if (f > 0.0 && f < 1.0) items.push_back({f, f, true});
  for (double f : b)
    if (f > 0.0 && f < 1.0) items.push_back({right_wrong ? f : 1.0 - f, f, false});
  std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) { return x.key < y.key; });
  const double tolerance = kStitchMergeLength / std::max({length_a, length_b, 1e-9});
  // A cluster is one division of each side, or of one side alone; its items are neighbours in the
  // sorted list, so the divisions of both sides keep one order. An item pairs with the nearer of
  // its neighbours: two cuts of one side near one cut of the other would otherwise leave the
  // farther one paired and the nearer one mapped onto the other side a hair from it.
  std::vector<std::vector<Item>> clusters;
  for (const Item& item : items) {
    if (!clusters.empty()) {
      std::vector<Item>& last = clusters.back();
      if (last.size() == 1 && last[0].on_a != item.on_a && item.key - last[0].key <= tolerance) {
        last.push_back(item);
        continue;
      }
      if (last.size() == 2 && last[0].on_a == item.on_a &&
          item.key - last[1].key < last[1].key - last[0].key) {
        const Item nearer = last[1];
        last.pop_back();
        clusters.push_back({nearer, item});
        continue;
      }
    }
    clusters.push_back({item});
  }
  a = {0.0};
  b = {0.0, 1.0};
  const auto mapped = [&](double f) { return right_wrong ? f : 1.0 - f; };
  for (const std::vector<Item>& cluster : clusters) {
    std::optional<double> own_a, own_b;
    for (const Item& item : cluster)
      (item.on_a ? own_a : own_b) = item.value;
    const double on_a = own_a ? *own_a : mapped(*own_b);
    a.push_back(on_a);
    b.push_back(own_b ? *own_b : mapped(on_a));
  }
  a.push_back(1.0);
  std::sort(b.begin(), b.end());
}

std::size_t nearest_index(const Divisions& divisions, double f) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < divisions.size(); ++i)
    if (std::abs(divisions[i] - f) < std::abs(divisions[best] - f)) best = i;
  return best;
}

bool kept(const std::string& name, const std::vector<std::string>& keep) {
  return std::any_of(keep.begin(), keep.end(), [&](const std::string& word) {
    return !word.empty() && name.find(word) != std::string::npos;
  });
}

std::string cell_name(const std::string& panel, int row, int column, int part) {
  std::string name = panel + "__r" + std::to_string(row) + "c" + std::to_string(column);
  if (part >= 0) name += static_cast<char>('a' + part % 26);
  if (part >= 26) name += std::to_string(part / 26);
  return name;
}

QuiltResult quilt(const Pattern& pattern, const QuiltOptions& options) {
  if (!(options.cell > 0.0) || !std::isfinite(options.cell))
    throw_input_error(pattern.source, "", "the cell size must be a positive number of metres");
  const double units = pattern.units_in_meter;
  QuiltResult result;
  result.smallest_piece_area = std::numeric_limits<double>::infinity();

  // Cut every panel; remember its pieces and edge samples.
  std::vector<std::vector<SampledEdge>> samples(pattern.panels.size());
  std::vector<std::vector<Piece>> pieces(pattern.panels.size());
  int next_cut_id = 0;
  for (std::size_t p = 0; p < pattern.panels.size(); ++p) {
    const Panel& panel = pattern.panels[p];
    for (const PanelEdge& edge : panel.edges)
      samples[p].push_back(sample_edge(panel, edge));
    pieces[p] = {flatten(samples[p])};
    if (kept(panel.name, options.keep)) {
      ++result.kept_panels;
      continue;
    }
    const std::string place = "panel '" + panel.name + "'";
    pieces[p] =
        cut_along(std::move(pieces[p]), 0, options.cell, next_cut_id, place, pattern.source);
    pieces[p] =
        cut_along(std::move(pieces[p]), 1, options.cell, next_cut_id, place, pattern.source);
    merge_small_pieces(pieces[p], kSmallestPiece * options.cell * options.cell);
    if (pieces[p].size() > 1)
      for (const Piece& piece : pieces[p])
        result.smallest_piece_area =
            std::min(result.smallest_piece_area, std::abs(polygon_signed_area(piece.points)));
  }

  // Divisions of every original edge: where the cuts end on it, then matched across stitches.
  std::vector<std::vector<Divisions>> divisions(pattern.panels.size());
  for (std::size_t p = 0; p < pattern.panels.size(); ++p) {
    divisions[p].assign(pattern.panels[p].edges.size(), Divisions{0.0, 1.0});
    for (const Piece& piece : pieces[p])
      for (const Run& run : runs_of(piece))
        if (run.edge >= 0) {
          const double length = samples[p][run.edge].length();
          divisions[p][run.edge].push_back(run.s0 / length);
          divisions[p][run.edge].push_back(run.s1 / length);
        }
    for (Divisions& d : divisions[p]) {
      std::sort(d.begin(), d.end());
      d.erase(std::unique(d.begin(), d.end()), d.end());
    }
  }
  for (const Stitch& stitch : pattern.stitches)
    match_divisions(divisions[stitch.a.panel][stitch.a.edge],
                    divisions[stitch.b.panel][stitch.b.edge], stitch.right_wrong,
                    samples[stitch.a.panel][stitch.a.edge].length(),
                    samples[stitch.b.panel][stitch.b.edge].length());

  // Write the pieces. parts[p][e][k]: the output panel and edge of part k of edge e of panel p.
  struct Side {
    std::string panel;
    int edge = -1;
  };
  std::vector<std::vector<std::vector<Side>>> parts(pattern.panels.size());
  Json panels = Json::object(), order = Json::array(), stitches = Json::array();
  std::map<std::pair<std::array<double, 2>, std::array<double, 2>>, Side> open_cuts;
  const auto stitch_json = [](const Side& a, const Side& b, bool right_wrong) {
    Json json = Json::array(
        {{{"panel", a.panel}, {"edge", a.edge}}, {{"panel", b.panel}, {"edge", b.edge}}});
    if (right_wrong) json.push_back("right_wrong");
    return json;
  };
  for (std::size_t p = 0; p < pattern.panels.size(); ++p) {
    const Panel& panel = pattern.panels[p];
    parts[p].resize(panel.edges.size());
    for (std::size_t e = 0; e < panel.edges.size(); ++e)
      parts[p][e].resize(divisions[p][e].size() - 1);
    std::map<std::pair<int, int>, int> in_square;  // pieces per grid square
    for (const Piece& piece : pieces[p])
      ++in_square[{piece.row, piece.column}];
    std::map<std::pair<int, int>, int> numbered;
    for (const Piece& piece : pieces[p]) {
      std::string name = panel.name;
      if (pieces[p].size() > 1) {
        const int part =
            in_square[{piece.row, piece.column}] > 1 ? numbered[{piece.row, piece.column}]++ : -1;
        name = cell_name(panel.name, piece.row, piece.column, part);
      }
      Json vertices = Json::array(), edges = Json::array();
      // Edge i runs from vertex i to vertex i + 1; the last one closes the loop below.
      const auto add_edge = [&](const Vector2d& from, Json curvature) {
        const int index = static_cast<int>(edges.size());
        vertices.push_back({from.x() * units, from.y() * units});
        Json edge = {{"endpoints", {index, index + 1}}};
        if (!curvature.is_null()) edge["curvature"] = std::move(curvature);
        edges.push_back(std::move(edge));
        return index;
      };
      for (const Run& run : runs_of(piece)) {
        if (run.edge < 0) {
          const int index = add_edge(run.start, nullptr);
          const std::array<double, 2> from{run.start.x(), run.start.y()},
              to{run.end.x(), run.end.y()};
          const auto key = from < to ? std::make_pair(from, to) : std::make_pair(to, from);
          if (const auto other = open_cuts.find(key); other != open_cuts.end()) {
            stitches.push_back(stitch_json(other->second, {name, index}, false));
            open_cuts.erase(other);
          } else {
            open_cuts.emplace(key, Side{name, index});
          }
          continue;
        }
        const PanelEdge& edge = panel.edges[run.edge];
        const SampledEdge& sampled = samples[p][run.edge];
        const Divisions& d = divisions[p][run.edge];
        const std::size_t first = nearest_index(d, run.s0 / sampled.length());
        const std::size_t last = nearest_index(d, run.s1 / sampled.length());
        const EdgeCurve curve(panel, edge);
        for (std::size_t k = first; k < last; ++k) {
          const double u0 = sampled.parameter_at(d[k] * sampled.length());
          const double u1 = sampled.parameter_at(d[k + 1] * sampled.length());
          const Vector2d from = k == first ? run.start : curve.point(u0);
          const Vector2d to = k + 1 == last ? run.end : curve.point(u1);
          const int index = add_edge(from, curvature_of_part(panel, edge, u0, u1, from, to, units));
          parts[p][run.edge][k] = {name, index};
        }
      }
      edges.back()["endpoints"][1] = 0;  // the loop closes on the first vertex
      Json json = {
          {"translation",
           {panel.translation.x() * units, panel.translation.y() * units,
            panel.translation.z() * units}},
          {"rotation",
           {panel.rotation_degrees.x(), panel.rotation_degrees.y(), panel.rotation_degrees.z()}},
          {"vertices", std::move(vertices)},
          {"edges", std::move(edges)}};
      if (!panel.label.empty()) json["label"] = panel.label;
      panels[name] = std::move(json);
      order.push_back(name);
      ++result.pieces;
    }
  }
  if (!open_cuts.empty())
    throw_input_error(pattern.source, "piece '" + open_cuts.begin()->second.panel + "'",
                      "a cut could not be sewn: its two sides do not meet");
  for (const Stitch& stitch : pattern.stitches) {
    const auto& a = parts[stitch.a.panel][stitch.a.edge];
    const auto& b = parts[stitch.b.panel][stitch.b.edge];
    for (std::size_t k = 0; k < a.size(); ++k)
      stitches.push_back(
          stitch_json(a[k], b[stitch.right_wrong ? k : b.size() - 1 - k], stitch.right_wrong));
  }
  result.stitches = static_cast<int>(stitches.size());
  if (!std::isfinite(result.smallest_piece_area)) result.smallest_piece_area = 0.0;
  const Json specification = {
      {"pattern", {{"panels", panels}, {"stitches", stitches}, {"panel_order", order}}},
      {"properties", {{"units_in_meter", units}, {"curvature_coords", "relative"}}}};
  result.specification = specification.dump(1);
  return result;
}

}  // namespace quilting
}  // namespace

QuiltResult quilt_pattern(const Pattern& pattern, const QuiltOptions& options) {
  return quilting::quilt(pattern, options);
}

}  // namespace garment
