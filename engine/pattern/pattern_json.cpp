// GarmentCode JSON import with validation. Rejected, each with the file and the place:
// invalid or truncated JSON (line, column), nesting deeper than kMaxNesting, a key twice in one
// object, missing or wrongly typed keys, non-finite numbers, coordinates beyond 10 km, unknown
// curvature types, dangling panel/edge references in stitches, vertex indices out of range, edges
// that do not form one closed loop, an edge in two stitches, a stitch of an edge with itself,
// zero-length edges, self-intersecting outlines, an empty pattern, a panel name that is empty,
// holds a control character or begins or ends with a space (name_fault); past kMaxPanels panels or
// kMaxStitches stitches, BudgetError.

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <vector>

#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/core/text.h"
#include "engine/pattern/outline.h"
#include "engine/pattern/pattern.h"

namespace garment {
namespace {

using Json = nlohmann::json;

// Real specifications nest 6 levels deep; anything far deeper is not a pattern and would only cost
// stack in the parser.
constexpr int kMaxNesting = 64;

// Resource budgets, checked before any panel is read. GarmentCode's 500 random garments have at
// most 29 panels and 82 stitches, and the paper's largest example, a coat, 358 panels; past these
// a pattern is not a garment but a load test, whose later stages (classifier, seeding, contacts)
// would take minutes for nothing.
constexpr std::size_t kMaxPanels = 5000;
constexpr std::size_t kMaxStitches = 20000;

// No garment piece reaches 10 km: beyond this a coordinate (after the unit conversion) is a wrong
// unit or a corrupt number, and squaring it in areas and lengths would overflow.
constexpr double kMaxCoordinateMetres = 1e4;

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& place, const std::string& message) const {
    throw_input_error(source_, place, message);
  }

  const Json& member(const Json& object, const char* key, const std::string& place) const {
    if (!object.is_object()) fail(place, "expected a JSON object");
    const auto it = object.find(key);
    if (it == object.end()) fail(place, std::string("missing key \"") + key + "\"");
    return *it;
  }

  double number(const Json& value, const std::string& place, const std::string& what) const {
    if (!value.is_number()) fail(place, what + " must be a number");
    const double result = value.get<double>();
    if (!std::isfinite(result)) fail(place, what + " is not a finite number");
    return result;
  }

  int index(const Json& value, const std::string& place, const std::string& what) const {
    if (!value.is_number_integer() &&
        !(value.is_number_float() && is_integral(value.get<double>())))
      fail(place, what + " must be an integer");
    const double raw = value.get<double>();
    if (raw < 0 || raw > 1e9) fail(place, what + " is out of range (" + value.dump() + ")");
    return static_cast<int>(raw);
  }

  Eigen::Vector2d point(const Json& value, const std::string& place,
                        const std::string& what) const {
    if (!value.is_array() || value.size() != 2)
      fail(place, what + " must be an array of two numbers");
    return {number(value[0], place, what), number(value[1], place, what)};
  }

  Eigen::Vector3d triple(const Json& value, const std::string& place,
                         const std::string& what) const {
    if (!value.is_array() || value.size() != 3)
      fail(place, what + " must be an array of three numbers");
    return {number(value[0], place, what), number(value[1], place, what),
            number(value[2], place, what)};
  }

  const std::string& source() const { return source_; }

 private:
  static bool is_integral(double v) { return std::isfinite(v) && v == std::floor(v); }
  std::string source_;
};

// Throws unless both coordinates (metres) stay within kMaxCoordinateMetres.
void check_extent(const Eigen::Vector2d& metres, const std::string& place, const std::string& what,
                  const Reader& reader) {
  if (!(metres.cwiseAbs().maxCoeff() <= kMaxCoordinateMetres)) {
    std::ostringstream text;
    text << what << " lies " << metres.norm() << " m from the panel origin, beyond "
         << kMaxCoordinateMetres / 1000 << " km (check the numbers and \"units_in_meter\")";
    reader.fail(place, text.str());
  }
}

std::pair<int, int> line_and_column(const std::string& text, std::size_t byte) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < std::min(byte, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

void check_nesting(const std::string& text, const Reader& reader) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"')
      in_string = true;
    else if (c == '[' || c == '{') {
      if (++depth > kMaxNesting) {
        const auto [line, column] = line_and_column(text, i);
        reader.fail("line " + std::to_string(line) + ", column " + std::to_string(column),
                    "JSON nested deeper than " + std::to_string(kMaxNesting) + " levels");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// JSON allows a key twice in one object and nlohmann keeps the last value, which would silently
// drop a panel defined twice. This SAX handler builds the document as Json::parse does and refuses
// a duplicate key, naming the object (e.g. "pattern.panels"). (Json::parse's callback form would
// do too, but it rescans the parent container after every value: quadratic on large files.)
class NoDuplicateKeys {
 public:
  NoDuplicateKeys(Json& result, const Reader& reader) : dom_(result, true), reader_(reader) {}

  bool null() { return scalar(dom_.null()); }
  bool boolean(bool value) { return scalar(dom_.boolean(value)); }
  bool number_integer(Json::number_integer_t value) { return scalar(dom_.number_integer(value)); }
  bool number_unsigned(Json::number_unsigned_t value) {
    return scalar(dom_.number_unsigned(value));
  }
  bool number_float(Json::number_float_t value, const Json::string_t& text) {
    return scalar(dom_.number_float(value, text));
  }
  bool string(Json::string_t& value) { return scalar(dom_.string(value)); }
  bool binary(Json::binary_t& value) { return scalar(dom_.binary(value)); }
  bool start_object(std::size_t size) {
    open();
    return dom_.start_object(size);
  }
  bool key(Json::string_t& key) {
    if (!levels_.empty() && !levels_.back().keys.insert(key).second)
      reader_.fail(path(), "the key '" + key + "' appears twice");
    pending_key_ = key;
    return dom_.key(key);
  }
  bool end_object() {
    levels_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t size) {
    open();
    return dom_.start_array(size);
  }
  bool end_array() {
    levels_.pop_back();
    return dom_.end_array();
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& error) {
    return dom_.parse_error(position, token, error);
  }

 private:
  struct Level {
    std::string name;  // the key this object or array is the value of, "[]" in an array
    std::set<std::string> keys;
  };

  bool scalar(bool result) {
    pending_key_.clear();
    return result;
  }
  void open() {
    levels_.push_back({pending_key_.empty() ? "[]" : pending_key_, {}});
    pending_key_.clear();
  }
  std::string path() const {
    std::string path;
    for (std::size_t i = 1; i < levels_.size(); ++i)
      path += (path.empty() || levels_[i].name == "[]" ? "" : ".") + levels_[i].name;
    return path.empty() ? std::string("top level") : path;
  }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  const Reader& reader_;
  std::vector<Level> levels_;
  std::string pending_key_;
};

Json parse_json(const std::string& text, const Reader& reader) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) reader.fail("", "the file is empty");
  check_nesting(text, reader);
  try {
    Json root;
    NoDuplicateKeys handler(root, reader);
    Json::sax_parse(text, &handler);
    return root;
  } catch (const Json::parse_error& error) {
    const auto [line, column] = line_and_column(text, error.byte > 0 ? error.byte - 1 : 0);
    std::string reason = error.what();
    // nlohmann prefixes "[json.exception.parse_error.101] parse error at line 1, column 2: ".
    if (const auto colon = reason.find(": "); colon != std::string::npos)
      reason = reason.substr(colon + 2);
    const bool truncated = error.byte >= text.size();
    reader.fail("line " + std::to_string(line) + ", column " + std::to_string(column),
                std::string(truncated ? "truncated JSON: " : "invalid JSON: ") + reason);
  } catch (const Json::out_of_range& error) {
    // Numbers beyond double range ("1e999"): nlohmann names the token but not its position.
    std::string reason = error.what();
    std::string place;
    const auto open = reason.find('\''), close = reason.rfind('\'');
    if (open != std::string::npos && close > open) {
      const std::string token = reason.substr(open + 1, close - open - 1);
      if (const auto at = text.find(token); !token.empty() && at != std::string::npos) {
        const auto [line, column] = line_and_column(text, at);
        place = "line " + std::to_string(line) + ", column " + std::to_string(column);
      }
    }
    reader.fail(place, "number out of range: " +
                           (open != std::string::npos ? reason.substr(open) : reason));
  }
}

PanelEdge read_edge(const Json& json, const Panel& panel, int edge_index, double scale,
                    const Reader& reader) {
  const std::string place = "panel '" + panel.name + "', edge " + std::to_string(edge_index);
  if (!json.is_object()) reader.fail(place, "an edge must be a JSON object");
  PanelEdge edge;
  const Json& endpoints = reader.member(json, "endpoints", place);
  if (!endpoints.is_array() || endpoints.size() != 2)
    reader.fail(place, "\"endpoints\" must be an array of two vertex indices");
  edge.start = reader.index(endpoints[0], place, "endpoint");
  edge.end = reader.index(endpoints[1], place, "endpoint");
  const int vertex_count = static_cast<int>(panel.vertices.size());
  for (int endpoint : {edge.start, edge.end})
    if (endpoint >= vertex_count)
      reader.fail(place, "vertex index " + std::to_string(endpoint) +
                             " out of range (the panel has " + std::to_string(vertex_count) +
                             " vertices)");
  if (const auto label = json.find("label"); label != json.end() && label->is_string())
    edge.label = label->get<std::string>();

  const auto curvature_it = json.find("curvature");
  if (curvature_it == json.end() || curvature_it->is_null()) return edge;
  const Json& curvature = *curvature_it;
  const Eigen::Vector2d start = panel.vertices[edge.start];
  const Eigen::Vector2d chord = panel.vertices[edge.end] - start;
  const Eigen::Vector2d perpendicular(-chord.y(), chord.x());
  const auto relative_point = [&](const Json& value) {
    const Eigen::Vector2d ts = reader.point(value, place, "a curvature control point [t, s]");
    const Eigen::Vector2d control = start + ts.x() * chord + ts.y() * perpendicular;
    check_extent(control, place, "a curvature control point", reader);
    return control;
  };
  if (curvature
          .is_array()) {  // Garment-Pattern-Generator's older form: one quadratic control [t, s]
    edge.kind = CurveKind::Quadratic;
    edge.controls.push_back(relative_point(curvature));
    return edge;
  }
  if (!curvature.is_object())
    reader.fail(place, "\"curvature\" must be an object or an [t, s] array");
  const Json& type = reader.member(curvature, "type", place + " curvature");
  if (!type.is_string()) reader.fail(place, "curvature \"type\" must be a string");
  const std::string kind = type.get<std::string>();
  const Json& params = reader.member(curvature, "params", place + " curvature");
  if (!params.is_array()) reader.fail(place, "curvature \"params\" must be an array");
  if (kind == "quadratic" || kind == "cubic") {
    const std::size_t expected = kind == "quadratic" ? 1 : 2;
    if (params.size() != expected)
      reader.fail(place,
                  kind + " curvature needs " + std::to_string(expected) + " control point(s)");
    edge.kind = kind == "quadratic" ? CurveKind::Quadratic : CurveKind::Cubic;
    for (const Json& control : params)
      edge.controls.push_back(relative_point(control));
  } else if (kind == "circle") {
    if (params.size() != 3) reader.fail(place, "circle curvature needs [radius, large_arc, right]");
    edge.kind = CurveKind::Circle;
    edge.radius = reader.number(params[0], place, "circle radius") * scale;
    if (!(edge.radius <= kMaxCoordinateMetres)) {
      std::ostringstream text;
      text << "circle radius " << edge.radius << " m is beyond " << kMaxCoordinateMetres / 1000
           << " km (check the numbers and \"units_in_meter\")";
      reader.fail(place, text.str());
    }
    if (!(edge.radius > 0.0)) reader.fail(place, "circle radius must be positive");
    edge.large_arc = reader.number(params[1], place, "circle large_arc flag") != 0.0;
    edge.right = reader.number(params[2], place, "circle right flag") != 0.0;
  } else {
    reader.fail(place,
                "unknown curvature type \"" + kind + "\" (expected quadratic, cubic or circle)");
  }
  return edge;
}

Panel read_panel(const std::string& name, const Json& json, double scale, const Reader& reader) {
  const std::string place = "panel '" + name + "'";
  if (!json.is_object()) reader.fail(place, "a panel must be a JSON object");
  Panel panel;
  panel.name = name;
  const Json& vertices = reader.member(json, "vertices", place);
  if (!vertices.is_array()) reader.fail(place, "\"vertices\" must be an array");
  if (vertices.size() < 2) reader.fail(place, "a panel needs at least two vertices");
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const std::string vertex_place = place + ", vertex " + std::to_string(i);
    panel.vertices.push_back(scale * reader.point(vertices[i], vertex_place, "a vertex"));
    check_extent(panel.vertices.back(), vertex_place, "the vertex", reader);
  }
  const Json& edges = reader.member(json, "edges", place);
  if (!edges.is_array()) reader.fail(place, "\"edges\" must be an array");
  if (edges.size() < 2) reader.fail(place, "a panel outline needs at least two edges");
  for (std::size_t e = 0; e < edges.size(); ++e)
    panel.edges.push_back(read_edge(edges[e], panel, static_cast<int>(e), scale, reader));
  for (std::size_t e = 0; e < panel.edges.size(); ++e) {
    const PanelEdge& edge = panel.edges[e];
    const std::size_t next = (e + 1) % panel.edges.size();
    if (edge.end != panel.edges[next].start)
      reader.fail(place + ", edge " + std::to_string(e),
                  "edges do not form one closed loop: edge " + std::to_string(e) +
                      " ends at vertex " + std::to_string(edge.end) + " but edge " +
                      std::to_string(next) + " starts at vertex " +
                      std::to_string(panel.edges[next].start));
  }
  if (const auto rotation = json.find("rotation"); rotation != json.end())
    panel.rotation_degrees = reader.triple(*rotation, place, "\"rotation\"");
  if (const auto translation = json.find("translation"); translation != json.end())
    panel.translation = scale * reader.triple(*translation, place, "\"translation\"");
  if (const auto label = json.find("label"); label != json.end() && label->is_string())
    panel.label = label->get<std::string>();
  return panel;
}

EdgeRef read_stitch_side(const Json& json, const Pattern& pattern,
                         const std::map<std::string, int>& panel_of_name, const std::string& place,
                         const Reader& reader) {
  if (!json.is_object())
    reader.fail(place, "a stitch side must be an object {\"panel\", \"edge\"}");
  const Json& panel_name = reader.member(json, "panel", place);
  if (!panel_name.is_string()) reader.fail(place, "\"panel\" must be a panel name");
  EdgeRef side;
  const auto found = panel_of_name.find(panel_name.get<std::string>());
  side.panel = found == panel_of_name.end() ? -1 : found->second;
  if (side.panel < 0)
    reader.fail(place, "panel '" + panel_name.get<std::string>() + "' does not exist");
  side.edge = reader.index(reader.member(json, "edge", place), place, "\"edge\"");
  const Panel& panel = pattern.panels[side.panel];
  if (side.edge >= static_cast<int>(panel.edges.size()))
    reader.fail(place, "edge " + std::to_string(side.edge) + " does not exist on panel '" +
                           panel.name + "' (it has " + std::to_string(panel.edges.size()) +
                           " edges)");
  return side;
}

}  // namespace

int Pattern::panel_index(const std::string& name) const {
  for (std::size_t i = 0; i < panels.size(); ++i)
    if (panels[i].name == name) return static_cast<int>(i);
  return -1;
}

Eigen::Matrix3d panel_rotation(const Eigen::Vector3d& rotation_degrees) {
  const Eigen::Vector3d radians = rotation_degrees * (std::numbers::pi / 180.0);
  const Eigen::Matrix3d rx =
      Eigen::AngleAxisd(radians.x(), Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d ry =
      Eigen::AngleAxisd(radians.y(), Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d rz =
      Eigen::AngleAxisd(radians.z(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return rz * ry * rx;
}

Pattern parse_pattern(const std::string& json_text, const std::string& source) {
  const Reader reader(source);
  const Json root = parse_json(json_text, reader);
  if (!root.is_object()) reader.fail("", "the top level must be a JSON object");
  Pattern pattern;
  pattern.source = source;
  if (const auto properties = root.find("properties"); properties != root.end()) {
    if (!properties->is_object()) reader.fail("properties", "must be an object");
    if (const auto units = properties->find("units_in_meter"); units != properties->end()) {
      pattern.units_in_meter = reader.number(*units, "properties", "\"units_in_meter\"");
      if (!(pattern.units_in_meter > 0.0))
        reader.fail("properties", "\"units_in_meter\" must be positive");
    }
    if (const auto coords = properties->find("curvature_coords"); coords != properties->end())
      if (!coords->is_string() || coords->get<std::string>() != "relative")
        reader.fail("properties", "only \"curvature_coords\": \"relative\" is supported");
  }
  const double scale = 1.0 / pattern.units_in_meter;

  const Json& body = reader.member(root, "pattern", "top level");
  const Json& panels = reader.member(body, "panels", "pattern");
  if (!panels.is_object()) reader.fail("pattern", "\"panels\" must be an object {name: panel}");
  if (panels.empty()) reader.fail("pattern", "the pattern has no panels");
  const Json& stitches = reader.member(body, "stitches", "pattern");
  if (!stitches.is_array()) reader.fail("pattern", "\"stitches\" must be an array");
  if (panels.size() > kMaxPanels)
    throw BudgetError(source + ": the pattern has " + std::to_string(panels.size()) +
                      " panels, over the budget of " + std::to_string(kMaxPanels));
  if (stitches.size() > kMaxStitches)
    throw BudgetError(source + ": the pattern has " + std::to_string(stitches.size()) +
                      " stitches, over the budget of " + std::to_string(kMaxStitches));

  std::vector<std::string> order;
  std::set<std::string> ordered;  // the names in `order`
  if (const auto panel_order = body.find("panel_order"); panel_order != body.end()) {
    if (!panel_order->is_array())
      reader.fail("pattern", "\"panel_order\" must be an array of names");
    for (const Json& name : *panel_order) {
      if (!name.is_string()) reader.fail("pattern", "\"panel_order\" must be an array of names");
      if (!panels.contains(name.get<std::string>()))
        reader.fail("pattern", "\"panel_order\" names panel '" + name.get<std::string>() +
                                   "', which does not exist");
      if (!ordered.insert(name.get<std::string>()).second)
        reader.fail("pattern",
                    "\"panel_order\" names panel '" + name.get<std::string>() + "' twice");
      order.push_back(name.get<std::string>());
    }
  }
  for (const auto& [name, value] : panels.items())
    if (!ordered.count(name)) order.push_back(name);
  for (const std::string& name : order) {
    // Names are data: every export writes them as they are (an OBJ `g` line, a glTF name), so a
    // name that would break a line or vanish is refused here, once for every writer.
    if (const std::string fault = name_fault(name); !fault.empty())
      reader.fail("pattern.panels, panel " + std::to_string(pattern.panels.size()),
                  "the panel name '" + name + "' is refused: " + fault);
    pattern.panels.push_back(read_panel(name, panels[name], scale, reader));
  }

  std::map<std::string, int> panel_of_name;
  for (std::size_t p = 0; p < pattern.panels.size(); ++p)
    panel_of_name.emplace(pattern.panels[p].name, static_cast<int>(p));
  std::map<std::pair<int, int>, int> stitch_of_edge;
  for (std::size_t s = 0; s < stitches.size(); ++s) {
    const std::string place = "stitch " + std::to_string(s);
    const Json& json = stitches[s];
    if (!json.is_array() || json.size() < 2 || json.size() > 3)
      reader.fail(
          place,
          "a stitch must be [{panel, edge}, {panel, edge}] with an optional \"right_wrong\"");
    Stitch stitch;
    stitch.file_index = static_cast<int>(s);
    stitch.a = read_stitch_side(json[0], pattern, panel_of_name, place + " side 0", reader);
    stitch.b = read_stitch_side(json[1], pattern, panel_of_name, place + " side 1", reader);
    if (json.size() == 3) {
      if (!json[2].is_string() || json[2].get<std::string>() != "right_wrong")
        reader.fail(place, "the third element of a stitch can only be \"right_wrong\"");
      stitch.right_wrong = true;
    }
    if (stitch.a.panel == stitch.b.panel && stitch.a.edge == stitch.b.edge)
      reader.fail(place, "stitches edge " + std::to_string(stitch.a.edge) + " of panel '" +
                             pattern.panels[stitch.a.panel].name + "' to itself");
    for (const EdgeRef& side : {stitch.a, stitch.b}) {
      const auto [it, inserted] =
          stitch_of_edge.try_emplace({side.panel, side.edge}, static_cast<int>(s));
      if (!inserted)
        reader.fail(place, "edge " + std::to_string(side.edge) + " of panel '" +
                               pattern.panels[side.panel].name + "' is already sewn by stitch " +
                               std::to_string(it->second));
    }
    pattern.stitches.push_back(stitch);
  }

  for (std::size_t p = 0; p < pattern.panels.size(); ++p)
    validate_outline(pattern, static_cast<int>(p), build_outline(pattern.panels[p]));
  return pattern;
}

Pattern load_pattern(const std::filesystem::path& path) {
  Pattern pattern = parse_pattern(read_file(path), path.string());
  protect_input_file(path);
  return pattern;
}

}  // namespace garment
