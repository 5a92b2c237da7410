#include "engine/io/garment_obj.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/core/text.h"

namespace garment {
namespace {

// vt must match a pattern position to this distance, in metres (converted to file units).
constexpr double kMatchToleranceMetres = 1e-6;

struct Corner {
  int vertex = 0;  // 0-based into the file's v list
  int uv = 0;      // 0-based into the file's vt list
  int line = 0;
};

struct Group {
  int line = 0;  // first `g` line
  std::vector<Corner> corners;
};

// The parts of an OBJ file a garment needs: v, vt, and the faces' corners by `g` group.
class ObjParser {
 public:
  explicit ObjParser(const std::string& source) : source_(source) {}

  void parse(std::string_view text) {
    int line_number = 0;
    Group* group = nullptr;
    std::size_t start = 0;
    while (start < text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(start, end - start);
      start = end + 1;
      ++line_number;
      line_ = line_number;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      const std::string_view keyword = next_word(line);
      if (keyword.empty() || keyword.front() == '#') continue;
      if (keyword == "v") {
        // One statement per number: the order of evaluation of arguments is unspecified.
        const double x = number(line);
        const double y = number(line);
        vertices_.emplace_back(x, y, number(line));
      } else if (keyword == "vt") {
        const double u = number(line);
        uvs_.emplace_back(u, number(line));
      } else if (keyword == "g") {
        const std::string name(trim(line));
        if (name.empty()) fail("a `g` line without a group name");
        auto [it, inserted] = groups_.try_emplace(name);
        if (inserted) it->second.line = line_number;
        group = &it->second;
      } else if (keyword == "f") {
        if (!group) fail("a face outside of any `g` group (one group per panel is expected)");
        int corner_count = 0;
        for (std::string_view word = next_word(line); !word.empty(); word = next_word(line)) {
          group->corners.push_back(corner(word));
          ++corner_count;
        }
        if (corner_count < 3) fail("a face needs at least 3 corners");
      }
      // vn, o, s, usemtl, mtllib, l, ...: not part of the garment's geometry.
    }
  }

  const std::string& source_;
  int line_ = 0;
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Eigen::Vector2d> uvs_;
  std::map<std::string, Group> groups_;

  [[noreturn]] void fail(const std::string& message) const {
    throw_input_error(source_, "line " + std::to_string(line_), message);
  }

 private:
  static std::string_view trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
  }

  static std::string_view next_word(std::string_view& line) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
      line = {};
      return {};
    }
    line.remove_prefix(first);
    const auto length = std::min(line.find_first_of(" \t"), line.size());
    const std::string_view word = line.substr(0, length);
    line.remove_prefix(length);
    return word;
  }

  double number(std::string_view& line) const {
    const std::string_view word = next_word(line);
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || error != std::errc() || end != word.data() + word.size())
      fail(word.empty() ? std::string("a number is missing")
                        : std::string(word).append(" is not a number"));
    if (!std::isfinite(value)) fail("a number is not finite");
    return value;
  }

  // OBJ indices are 1-based, or negative relative to the end of the list so far.
  int index(std::string_view word, std::size_t count, const char* what) const {
    long value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || error != std::errc() || end != word.data() + word.size())
      fail(std::string("bad ") + what + " index '" + std::string(word) + "'");
    const long resolved = value < 0 ? static_cast<long>(count) + value : value - 1;
    if (value == 0 || resolved < 0 || resolved >= static_cast<long>(count))
      fail(std::string(what) + " index " + std::to_string(value) + " out of range (" +
           std::to_string(count) + " so far)");
    return static_cast<int>(resolved);
  }

  Corner corner(std::string_view word) const {
    const auto slash = word.find('/');
    if (slash == std::string_view::npos || slash + 1 >= word.size() || word[slash + 1] == '/')
      fail("face corner '" + std::string(word) +
           "' has no vt: vertices are matched to the pattern by their vt");
    std::string_view uv = word.substr(slash + 1);
    uv = uv.substr(0, std::min(uv.find('/'), uv.size()));
    return {index(word.substr(0, slash), vertices_.size(), "vertex"), index(uv, uvs_.size(), "vt"),
            line_};
  }
};

void append_line(std::string& out, const char* format, double a, double b, double c = 0.0) {
  char buffer[128];
  const int length = std::snprintf(buffer, sizeof buffer, format, a, b, c);
  out.append(buffer, static_cast<std::size_t>(length));
}

}  // namespace

std::string format_garment_obj(const Garment& garment, const Eigen::MatrixX3d& positions) {
  std::vector<int> all(garment.pieces.size());
  std::iota(all.begin(), all.end(), 0);
  return format_garment_obj(garment, positions, all);
}

std::string format_garment_obj(const Garment& garment, const Eigen::MatrixX3d& positions,
                               const std::vector<int>& pieces) {
  if (positions.rows() != garment.vertex_count())
    throw std::invalid_argument("format_garment_obj: positions must have one row per vertex");
  int vertex_count = 0, triangle_count = 0;
  for (int p : pieces) {
    if (p < 0 || p >= static_cast<int>(garment.pieces.size()))
      throw std::invalid_argument("format_garment_obj: piece index out of range");
    vertex_count += garment.pieces[p].vertex_count;
    triangle_count += garment.pieces[p].triangle_count;
  }
  // A name is a whole `g` line: a line break inside it would start a line of its own and shift
  // every later vertex index. The pattern reader refuses such names; a garment built otherwise
  // is refused here rather than written wrong.
  for (int p : pieces)
    if (const std::string fault = name_fault(garment.pieces[p].name); !fault.empty())
      throw std::invalid_argument("format_garment_obj: piece " + std::to_string(p) + " '" +
                                  printable(garment.pieces[p].name) + "': " + fault);
  std::string out;
  out.reserve(static_cast<std::size_t>(vertex_count) * 90);
  // The source is a path, and a path may hold a line break.
  out += "# garment-studio garment from " + printable(garment.pattern.source) + "\n";
  char units[32];
  std::snprintf(units, sizeof units, "%g", garment.pattern.units_in_meter);
  out += "# v: metres, y up, body facing +z. vt: the pattern file's panel coordinates (" +
         std::string(units) + " units per metre).\n";
  out += "# " + std::to_string(pieces.size());
  if (pieces.size() != garment.pieces.size()) out += " of " + std::to_string(garment.pieces.size());
  out += " pieces, not welded; " + std::to_string(vertex_count) + " vertices, " +
         std::to_string(triangle_count) + " triangles\n";
  int written = 0;  // vertices of the pieces before this one in the file
  for (int p : pieces) {
    const Piece& piece = garment.pieces[p];
    out += "g " + piece.name + "\n";
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v)
      append_line(out, "v %.9g %.9g %.9g\n", positions(v, 0), positions(v, 1), positions(v, 2));
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v)
      append_line(out, "vt %.9g %.9g\n", garment.pattern_positions(v, 0),
                  garment.pattern_positions(v, 1));
    const int shift = written - piece.first_vertex + 1;  // global id → 1-based file index
    for (int t = piece.first_triangle; t < piece.first_triangle + piece.triangle_count; ++t) {
      const int a = garment.triangles(t, 0) + shift, b = garment.triangles(t, 1) + shift,
                c = garment.triangles(t, 2) + shift;
      char face[96];
      out.append(face, static_cast<std::size_t>(std::snprintf(
                           face, sizeof face, "f %d/%d %d/%d %d/%d\n", a, a, b, b, c, c)));
    }
    written += piece.vertex_count;
  }
  return out;
}

void write_garment_obj(const std::filesystem::path& path, const Garment& garment,
                       const Eigen::MatrixX3d& positions) {
  write_file_atomically(path, format_garment_obj(garment, positions));
}

void write_garment_obj(const std::filesystem::path& path, const Garment& garment,
                       const Eigen::MatrixX3d& positions, const std::vector<int>& pieces) {
  write_file_atomically(path, format_garment_obj(garment, positions, pieces));
}

Eigen::MatrixX3d parse_garment_obj(const std::string& text, const std::string& source,
                                   const Garment& garment) {
  ObjParser parser(source);
  parser.parse(text);
  const auto group_error = [&](const std::string& name, const std::string& message) -> void {
    throw_input_error(source, "group '" + name + "'", message);
  };
  for (const auto& [name, group] : parser.groups_)
    if (garment.pattern.panel_index(name) < 0)
      throw_input_error(source, "line " + std::to_string(group.line),
                        "group '" + name + "' is not a panel of " + garment.pattern.source);
  std::string missing;
  for (const Piece& piece : garment.pieces)
    if (!parser.groups_.count(piece.name)) missing += (missing.empty() ? "" : ", ") + piece.name;
  if (!missing.empty())
    throw_input_error(source, "",
                      "no group for the panels " + missing + " of " + garment.pattern.source);

  const double tolerance = kMatchToleranceMetres * garment.pattern.units_in_meter;
  Eigen::MatrixX3d positions(garment.vertex_count(), 3);
  for (const Piece& piece : garment.pieces) {
    const Group& group = parser.groups_.at(piece.name);
    // The vt of each file vertex used by the group (first corner wins; others must agree).
    std::unordered_map<int, Corner> corner_of_vertex;
    for (const Corner& corner : group.corners) {
      const auto [it, inserted] = corner_of_vertex.try_emplace(corner.vertex, corner);
      if (!inserted && (parser.uvs_[it->second.uv] - parser.uvs_[corner.uv]).norm() > tolerance)
        throw_input_error(source, "line " + std::to_string(corner.line),
                          "vertex " + std::to_string(corner.vertex + 1) +
                              " has two different vt in group '" + piece.name + "'");
    }
    if (static_cast<int>(corner_of_vertex.size()) != piece.vertex_count)
      group_error(piece.name, std::to_string(corner_of_vertex.size()) +
                                  " vertices, but the panel " + "meshed at " +
                                  std::to_string(garment.target_edge_length * 1000.0) + " mm has " +
                                  std::to_string(piece.vertex_count) +
                                  " (was the garment made with another edge length?)");
    // Pattern vertices of the piece sorted by u, for a window search around each vt.
    std::vector<int> by_u(static_cast<std::size_t>(piece.vertex_count));
    std::iota(by_u.begin(), by_u.end(), piece.first_vertex);
    std::sort(by_u.begin(), by_u.end(), [&](int a, int b) {
      return garment.pattern_positions(a, 0) < garment.pattern_positions(b, 0);
    });
    std::vector<char> matched(static_cast<std::size_t>(garment.vertex_count()), 0);
    for (const auto& [vertex, corner] : corner_of_vertex) {
      const Eigen::Vector2d uv = parser.uvs_[corner.uv];
      auto it =
          std::lower_bound(by_u.begin(), by_u.end(), uv.x() - tolerance,
                           [&](int v, double u) { return garment.pattern_positions(v, 0) < u; });
      int best = -1;
      double best_distance = tolerance;
      for (; it != by_u.end() && garment.pattern_positions(*it, 0) <= uv.x() + tolerance; ++it) {
        const double distance = (garment.pattern_positions.row(*it).transpose() - uv).norm();
        if (distance <= best_distance) {
          best_distance = distance;
          best = *it;
        }
      }
      char where[96];
      std::snprintf(where, sizeof where, "(%.9g, %.9g)", uv.x(), uv.y());
      if (best < 0)
        throw_input_error(
            source, "line " + std::to_string(corner.line),
            std::string("vt ") + where + " is not a mesh vertex of panel '" + piece.name + "'");
      if (matched[best])
        throw_input_error(
            source, "line " + std::to_string(corner.line),
            std::string("two vertices of group '") + piece.name + "' have the vt " + where);
      matched[best] = 1;
      positions.row(best) = parser.vertices_[vertex].transpose();
    }
  }
  return positions;
}

Eigen::MatrixX3d read_garment_obj(const std::filesystem::path& path, const Garment& garment) {
  return parse_garment_obj(read_file(path), path.string(), garment);
}

}  // namespace garment
