#pragma once
// The sewing pattern as read from a GarmentCode / Garment-Pattern-Generator JSON specification:
// panels (2D outlines of curved edges) and stitches (pairs of panel edges to be sewn). Coordinates
// are converted to metres on import; everything else is kept as the file has it, so that exports
// can speak the file's own coordinates. See ../shared/data/patterns/README.md for the format.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace garment {

enum class CurveKind { Straight, Quadratic, Cubic, Circle };

// One edge of a panel outline. Control points are absolute (panel-local, metres), already converted
// from the file's edge-relative [t, s] form.
struct PanelEdge {
  int start = 0;  // index into Panel::vertices
  int end = 0;
  CurveKind kind = CurveKind::Straight;
  std::vector<Eigen::Vector2d> controls;  // 1 for quadratic, 2 for cubic
  double radius = 0.0;                    // circle: arc radius (metres)
  bool large_arc = false;                 // circle: the arc spans more than 180°
  bool right = false;  // circle: bulges to the right of start→end (SVG sweep flag)
  std::string label;
};

struct Panel {
  std::string name;
  std::vector<Eigen::Vector2d> vertices;                       // panel-local, metres, y up
  std::vector<PanelEdge> edges;                                // one closed loop in list order
  Eigen::Vector3d rotation_degrees = Eigen::Vector3d::Zero();  // Euler angles, R = Rz·Ry·Rx
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // metres; only the flat reference uses it
  std::string label;
};

struct EdgeRef {
  int panel = 0;  // index into Pattern::panels
  int edge = 0;   // index into Panel::edges
};

// A stitch joins two edges. Default pairing is reversed (a.start ↔ b.end); right_wrong keeps the
// same direction (a.start ↔ b.start). A stitch whose two edges lie on one panel is a dart.
struct Stitch {
  EdgeRef a;
  EdgeRef b;
  bool right_wrong = false;
  int file_index = 0;  // position in the file's stitch list, for messages
  bool is_dart() const { return a.panel == b.panel; }
};

struct Pattern {
  std::string source;             // file name for messages
  double units_in_meter = 100.0;  // as in the file (100 = centimetres)
  std::vector<Panel> panels;      // in the file's panel_order when present, else name order
  std::vector<Stitch> stitches;   // darts included (Stitch::is_dart)

  int panel_index(const std::string& name) const;  // -1 when absent
};

// Rotation of a panel into the 3D frame of its file, R = Rz·Ry·Rx (degrees), as GarmentCode's
// loader.
Eigen::Matrix3d panel_rotation(const Eigen::Vector3d& rotation_degrees);

// Parses and validates a specification. `source` names the input in error messages. Throws
// InputError naming file and place for every malformed input (see pattern_json.cpp for the list).
Pattern parse_pattern(const std::string& json_text, const std::string& source);
Pattern load_pattern(const std::filesystem::path& path);

}  // namespace garment
