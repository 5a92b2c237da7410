// Torture suite (issue 9): malformed and extreme pattern and body files, generated here, each of
// which must end in a clear InputError that names the file and the place, or in a correct result,
// within bounded time and memory:
//   - wall time per case  ≤ kCaseSeconds × GARMENT_TEST_TIME_SCALE (env, default 1; the sanitizer
//     build sets it),
//   - peak resident memory of the load ≤ kCaseMegabytes (× 4 under AddressSanitizer).
// Patterns go through load_pattern + build_garment with the default MeshingOptions (20 mm, budget
// 400,000 vertices); bodies through load_body_obj. With GARMENT_ROBUSTNESS_TABLE=<file> the test
// writes the outcome of every case as the markdown table of docs/robustness.md.
// Every error message must be printable ASCII after the file's path: text quoted from the input
// (names, values, lines) is escaped (\x1b), never echoed raw to the terminal.
// Hostile paths (a FIFO, /dev/zero, a file over the input size limit) run in a child process that
// a timer kills and whose address space is capped, so that a reader that blocks or never ends
// fails its row instead of hanging the suite or exhausting the machine.

#include <QtTest>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern.h"
#include "support/test_environment.h"
#include "support/test_paths.h"

using namespace garment;
namespace fs = std::filesystem;

namespace {

// A hang guard, not a speed test (bench/ measures speed): the slowest case takes 6 s alone and
// shares CI's two cores with another test.
constexpr double kCaseSeconds = 30.0;
constexpr double kCaseMegabytes = 1024.0;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif
constexpr double kMemoryScale = kAddressSanitizer ? 4.0 : 1.0;
// The address space of a child running a hostile path: far above what a refusal needs, far below
// what reading /dev/zero without a cap would take from the machine. (AddressSanitizer reserves
// terabytes of address space up front: no cap there.)
constexpr rlim_t kChildAddressSpace = rlim_t{4} << 30;

// Peak resident set since the last reset_peak_memory(), in MiB (Linux: VmHWM, reset through
// /proc/self/clear_refs).
void reset_peak_memory() {
  std::ofstream("/proc/self/clear_refs") << "5";
}
double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
  return 0.0;
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string random_bytes(std::size_t count, unsigned seed) {
  std::mt19937 random(seed);
  std::string bytes(count, '\0');
  for (char& byte : bytes)
    byte = static_cast<char>(random() & 0xff);
  return bytes;
}

// --- pattern generators -------------------------------------------------------------------------

// A w×h (cm) rectangle panel with straight edges, as a JSON member "name": {...}.
std::string rectangle_panel(const std::string& name, double w, double h) {
  std::ostringstream out;
  out << "\"" << name << "\": {\"vertices\": [[0,0],[" << w << ",0],[" << w << "," << h << "],[0,"
      << h << "]], \"edges\": [{\"endpoints\":[0,1]},{\"endpoints\":[1,2]},"
      << "{\"endpoints\":[2,3]},{\"endpoints\":[3,0]}]}";
  return out.str();
}

std::string pattern_json(const std::vector<std::string>& panels, const std::string& stitches,
                         const std::string& properties = "") {
  std::string text = "{";
  if (!properties.empty()) text += "\"properties\": {" + properties + "}, ";
  text += "\"pattern\": {\"panels\": {";
  for (std::size_t i = 0; i < panels.size(); ++i)
    text += (i ? ",\n" : "") + panels[i];
  return text + "}, \"stitches\": [" + stitches + "]}}";
}

std::string two_rectangles() {
  return pattern_json({rectangle_panel("front", 40, 60), rectangle_panel("back", 40, 60)},
                      R"([{"panel":"front","edge":1},{"panel":"back","edge":3}])");
}

// A regular polygon of `count` vertices (radius in cm), one straight edge per side.
std::string polygon_panel(const std::string& name, int count, double radius) {
  std::string text = "\"" + name + "\": {\"vertices\": [";
  char number[64];
  for (int i = 0; i < count; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / count;
    std::snprintf(number, sizeof number, "%s[%.9g,%.9g]", i ? "," : "", radius * std::cos(angle),
                  radius * std::sin(angle));
    text += number;
  }
  text += "], \"edges\": [";
  for (int i = 0; i < count; ++i)
    text += std::string(i ? "," : "") + "{\"endpoints\":[" + std::to_string(i) + "," +
            std::to_string((i + 1) % count) + "]}";
  return text + "]}";
}

// --- body generators ----------------------------------------------------------------------------

// A closed cube of side `size` (file units) centred at the origin, faces outward unless `inward`.
std::string cube_obj(double size, bool inward = false, bool drop_last_face = false) {
  std::ostringstream out;
  const double s = size / 2;
  for (int i = 0; i < 8; ++i)
    out << "v " << (i & 1 ? s : -s) << ' ' << (i & 2 ? s : -s) << ' ' << (i & 4 ? s : -s) << '\n';
  const int faces[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5},
                           {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
  for (int f = 0; f < (drop_last_face ? 5 : 6); ++f) {
    out << 'f';
    if (inward)
      for (int k = 3; k >= 0; --k)
        out << ' ' << faces[f][k];
    else
      for (int k = 0; k < 4; ++k)
        out << ' ' << faces[f][k];
    out << '\n';
  }
  return out.str();
}

// A closed UV sphere (radius 0.3 m, centre 1 m up) with about `rings` × `segments` vertices.
std::string sphere_obj(int rings, int segments) {
  std::string out;
  out.reserve(static_cast<std::size_t>(rings) * segments * 40);
  char line[128];
  std::snprintf(line, sizeof line, "v 0 1.3 0\nv 0 0.7 0\n");
  out += line;
  for (int r = 1; r < rings; ++r) {
    const double polar = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double azimuth = 2.0 * std::numbers::pi * s / segments;
      std::snprintf(line, sizeof line, "v %.9f %.9f %.9f\n",
                    0.3 * std::sin(polar) * std::cos(azimuth), 1.0 + 0.3 * std::cos(polar),
                    0.3 * std::sin(polar) * std::sin(azimuth));
      out += line;
    }
  }
  const auto id = [&](int r, int s) { return 3 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    std::snprintf(line, sizeof line, "f 1 %d %d\n", id(1, s + 1), id(1, s));
    out += line;
    std::snprintf(line, sizeof line, "f 2 %d %d\n", id(rings - 1, s), id(rings - 1, s + 1));
    out += line;
  }
  for (int r = 1; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      std::snprintf(line, sizeof line, "f %d %d %d %d\n", id(r, s), id(r, s + 1), id(r + 1, s + 1),
                    id(r + 1, s));
      out += line;
    }
  return out;
}

// --- cases --------------------------------------------------------------------------------------

enum class Kind { Pattern, Body };

struct Outcome {
  bool error = false;
  std::string message;  // the error, or a summary of the result
};

struct Case {
  std::string name;
  Kind kind;
  std::string file_name;                 // inside the case's folder
  std::function<std::string()> content;  // the file's bytes; empty function = no file written
  // Expected: an InputError containing every fragment (the file's path is always required first),
  // or, when `check` is set, a result that `check` accepts (returns "" or a failure message).
  std::vector<std::string> fragments;
  std::function<std::string(const Outcome&)> check;
  bool budget_error = false;  // the error must be a BudgetError
};

// A case whose input is not written from `content` but made in the case's folder (a FIFO, a
// sparse file) or named (/dev/zero) by `make`, which returns its path. It runs in a child process.
struct HostileCase {
  Case expected;
  std::function<fs::path(const fs::path& dir)> make;
};

struct Row {
  std::string name, kind, input, outcome, message;
  double seconds = 0.0, megabytes = 0.0;
  bool passed = false;
};

std::vector<Row>& table() {
  static std::vector<Row> rows;
  return rows;
}

std::string human_size(std::size_t bytes) {
  char text[32];
  if (bytes >= (1u << 20))
    std::snprintf(text, sizeof text, "%.1f MB", bytes / 1048576.0);
  else if (bytes >= 1024)
    std::snprintf(text, sizeof text, "%.1f kB", bytes / 1024.0);
  else
    std::snprintf(text, sizeof text, "%zu B", bytes);
  return text;
}

std::vector<Case> cases() {
  std::vector<Case> all;
  const auto pattern_error = [&](std::string name, std::string file, std::function<std::string()> c,
                                 std::vector<std::string> fragments) {
    all.push_back({std::move(name), Kind::Pattern, std::move(file), std::move(c),
                   std::move(fragments), nullptr, false});
  };
  const auto body_error = [&](std::string name, std::function<std::string()> c,
                              std::vector<std::string> fragments) {
    all.push_back({std::move(name), Kind::Body, "body.obj", std::move(c), std::move(fragments),
                   nullptr, false});
  };
  const auto real_pattern = [] {
    return read_text(test::test_data("patterns/gc_0005_specification.json"));
  };

  // Patterns.
  pattern_error("pattern: empty file", "p.json", [] { return std::string(); },
                {"the file is empty"});
  pattern_error("pattern: only whitespace", "p.json", [] { return std::string(" \n\t\r\n"); },
                {"the file is empty"});
  pattern_error("pattern: truncated (real file cut in half)", "p.json",
                [&] {
                  const std::string text = real_pattern();
                  return text.substr(0, text.size() / 2);
                },
                {"line ", "column ", "truncated JSON"});
  pattern_error("pattern: binary garbage (64 kB random bytes)", "p.json",
                [] { return random_bytes(65536, 7); }, {"line 1, column", "invalid JSON"});
  pattern_error("pattern: NUL bytes inside a real file", "p.json",
                [&] {
                  std::string text = real_pattern();
                  text[text.size() / 3] = '\0';
                  return text;
                },
                {"line ", "invalid JSON"});
  pattern_error("pattern: huge number 1e999", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(text.find("[40,0]"), 6, "[1e999,0]");
                  return text;
                },
                {"line 1, column 55", "number out of range"});
  pattern_error("pattern: huge coordinates 1e300 (finite)", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(text.find("[40,0]"), 6, "[1e300,0]");
                  return text;
                },
                {"panel 'front', vertex 1", "beyond 10 km"});
  pattern_error("pattern: tiny units_in_meter 1e-300 (coordinates overflow)", "p.json",
                [] {
                  return pattern_json({rectangle_panel("front", 40, 60)}, "",
                                      "\"units_in_meter\": 1e-300");
                },
                {"panel 'front', vertex 1", "units_in_meter"});
  pattern_error("pattern: NaN literal", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(text.find("[40,0]"), 6, "[NaN,0]");
                  return text;
                },
                {"line 1, column 55", "invalid JSON"});
  pattern_error("pattern: Infinity literal", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(text.find("[40,0]"), 6, "[Infinity,0]");
                  return text;
                },
                {"line 1, column 55", "invalid JSON"});
  pattern_error("pattern: circle radius 1e300", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(
                      text.find("{\"endpoints\":[0,1]}"), 19,
                      R"({"endpoints":[0,1],"curvature":{"type":"circle","params":[1e300,0,1]}})");
                  return text;
                },
                {"panel 'front', edge 0", "circle radius 1e+298 m is beyond 10 km"});
  pattern_error("pattern: deep nesting (100,000 arrays)", "p.json",
                [] { return std::string(100000, '[') + std::string(100000, ']'); },
                {"line 1, column 65", "nested deeper than 64"});
  pattern_error("pattern: deep nesting (100,000 objects, unterminated)", "p.json",
                [] {
                  std::string text;
                  for (int i = 0; i < 100000; ++i)
                    text += "{\"a\":";
                  return text;
                },
                {"line 1, column", "nested deeper than 64"});
  all.push_back({"pattern: 4,000 panels of 20×30 cm (over the vertex budget)",
                 Kind::Pattern,
                 "p.json",
                 [] {
                   std::vector<std::string> panels;
                   for (int i = 0; i < 4000; ++i)
                     panels.push_back(rectangle_panel("panel_" + std::to_string(i), 20, 30));
                   return pattern_json(panels, "");
                 },
                 {"vertices, over the budget of 400000"},
                 nullptr,
                 true});
  all.push_back({"pattern: 5,000 panels of 3×3 cm (the panel budget), 2,500 stitches",
                 Kind::Pattern,
                 "p.json",
                 [] {
                   std::vector<std::string> panels;
                   std::string stitches;
                   for (int i = 0; i < 5000; ++i) {
                     panels.push_back(rectangle_panel("panel_" + std::to_string(i), 3, 3));
                     if (i % 2)
                       stitches += std::string(i > 1 ? "," : "") + "[{\"panel\":\"panel_" +
                                   std::to_string(i - 1) + "\",\"edge\":1},{\"panel\":\"panel_" +
                                   std::to_string(i) + "\",\"edge\":3}]";
                   }
                   return pattern_json(panels, stitches);
                 },
                 {},
                 [](const Outcome& outcome) {
                   return outcome.message.find("5000 pieces") != std::string::npos
                              ? std::string()
                              : "expected 5000 pieces: " + outcome.message;
                 }});
  all.push_back({"pattern: 20,000 unconnected 1 cm squares (over the panel budget)",
                 Kind::Pattern,
                 "p.json",
                 [] {
                   std::vector<std::string> panels;
                   for (int i = 0; i < 20000; ++i)
                     panels.push_back(rectangle_panel("square_" + std::to_string(i), 1, 1));
                   return pattern_json(panels, "");
                 },
                 {"the pattern has 20000 panels, over the budget of 5000"},
                 nullptr,
                 true});
  all.push_back({"pattern: 20,001 stitches (darts of one 40,002-gon, over the stitch budget)",
                 Kind::Pattern,
                 "p.json",
                 [] {
                   std::string stitches;
                   for (int i = 0; i < 20001; ++i)
                     stitches += std::string(i ? "," : "") +
                                 "[{\"panel\":\"disc\",\"edge\":" + std::to_string(2 * i) +
                                 "},{\"panel\":\"disc\",\"edge\":" + std::to_string(2 * i + 1) +
                                 "}]";
                   return pattern_json({polygon_panel("disc", 40002, 100.0)}, stitches);
                 },
                 {"the pattern has 20001 stitches, over the budget of 20000"},
                 nullptr,
                 true});
  all.push_back({"pattern: 10^6-vertex outline (circle of radius 1 m)",
                 Kind::Pattern,
                 "p.json",
                 [] { return pattern_json({polygon_panel("disc", 1000000, 100.0)}, ""); },
                 {"vertices, over the budget of 400000"},
                 nullptr,
                 true});
  pattern_error("pattern: duplicate panel names", "p.json",
                [] {
                  return pattern_json(
                      {rectangle_panel("front", 40, 60), rectangle_panel("front", 30, 50)}, "");
                },
                {"pattern.panels", "'front'", "twice"});
  pattern_error("pattern: duplicate name in panel_order", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(text.find("\"panels\""), 0,
                               R"("panel_order": ["front", "back", "front"], )");
                  return text;
                },
                {"pattern", "names panel 'front' twice"});
  pattern_error("pattern: non-UTF-8 bytes in a panel name", "p.json",
                [] { return pattern_json({rectangle_panel("fr\xff\xfent", 40, 60)}, ""); },
                {"line 1, column", "invalid JSON", "UTF-8"});
  pattern_error("pattern: lone UTF-16 surrogate escape in a name", "p.json",
                [] { return pattern_json({rectangle_panel("a\\ud800b", 40, 60)}, ""); },
                {"line 1, column", "invalid JSON", "surrogate"});
  all.push_back({"pattern: non-UTF-8 file name, valid content",
                 Kind::Pattern,
                 "pattern_\xff\xfe.json",
                 two_rectangles,
                 {},
                 [](const Outcome& outcome) {
                   return outcome.message.find("2 pieces") != std::string::npos
                              ? std::string()
                              : "expected 2 pieces: " + outcome.message;
                 }});
  pattern_error("pattern: endpoint index 2^32", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(text.find("[0,1]"), 5, "[0,4294967296]");
                  return text;
                },
                {"panel 'front', edge 0", "out of range"});
  pattern_error("pattern: negative edge index in a stitch", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(text.find("\"edge\":1"), 8, "\"edge\":-1");
                  return text;
                },
                {"stitch 0 side 0", "out of range"});
  pattern_error("pattern: the top level is an array", "p.json", [] { return std::string("[1,2]"); },
                {"the top level must be a JSON object"});
  pattern_error("pattern: file is missing", "", nullptr, {"cannot open"});
  pattern_error("pattern: path is a directory", ".", nullptr, {"is a directory"});

  // Names are data: one that an export cannot write as it is is refused at import, with the
  // panel's place (the panel index in the pattern's order) and the name escaped.
  pattern_error("pattern: newline in a panel name", "p.json",
                [] { return pattern_json({rectangle_panel("front\\nv 0 0 0", 40, 60)}, ""); },
                {"pattern.panels, panel 0", "'front\\x0av 0 0 0'", "control character \\x0a"});
  pattern_error("pattern: empty panel name", "p.json",
                [] { return pattern_json({rectangle_panel("", 40, 60)}, ""); },
                {"pattern.panels, panel 0", "the name is empty"});
  pattern_error("pattern: NUL in a panel name", "p.json",
                [] { return pattern_json({rectangle_panel("fr\\u0000ont", 40, 60)}, ""); },
                {"pattern.panels, panel 0", "'fr\\x00ont'", "control character \\x00"});
  pattern_error("pattern: ESC in a panel name", "p.json",
                [] { return pattern_json({rectangle_panel("\\u001b[2Jfront", 40, 60)}, ""); },
                {"pattern.panels, panel 0", "'\\x1b[2Jfront'", "control character \\x1b"});
  pattern_error("pattern: panel name ending in a space", "p.json",
                [] {
                  return pattern_json(
                      {rectangle_panel("back", 40, 60), rectangle_panel("front ", 40, 60)}, "");
                },
                {"pattern.panels, panel 1", "begins or ends with a space"});
  pattern_error("pattern: ESC in a curvature type (quoted in the message)", "p.json",
                [] {
                  std::string text = two_rectangles();
                  text.replace(
                      text.find("{\"endpoints\":[0,1]}"), 19,
                      R"({"endpoints":[0,1],"curvature":{"type":"\u001b[2J","params":[]}})");
                  return text;
                },
                {"panel 'front', edge 0", "unknown curvature type \"\\x1b[2J\""});

  // Bodies.
  body_error("body: empty file", [] { return std::string(); }, {"no vertices"});
  body_error("body: binary garbage (64 kB random bytes)", [] { return random_bytes(65536, 11); },
             {""});
  body_error("body: truncated (sphere cut mid-line)",
             [] {
               const std::string text = sphere_obj(20, 20);
               return text.substr(0, text.size() * 2 / 3 + 3);
             },
             {"line "});
  body_error("body: open (cube without its last face)", [] { return cube_obj(1.0, false, true); },
             {"line ", "not closed"});
  all.push_back({"body: inside-out cube (all faces inward)",
                 Kind::Body,
                 "body.obj",
                 [] { return cube_obj(1.0, true); },
                 {},
                 [](const Outcome& outcome) {
                   return outcome.message.find("volume +1.000") != std::string::npos
                              ? std::string()
                              : "expected outward orientation (volume +1): " + outcome.message;
                 }});
  body_error("body: degenerate face (collinear corners)",
             [] { return cube_obj(1.0) + "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 9 10 11\n"; },
             {"line 18", "degenerate face"});
  body_error("body: all vertices coincide",
             [] { return std::string("v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n"); },
             {"all vertices coincide"});
  body_error("body: flat (zero volume, closed)",
             [] { return std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n"); },
             {"line ", ""});
  body_error("body: NaN coordinate", [] { return "v nan 0 0\n" + cube_obj(1.0); },
             {"line 1", "not finite"});
  body_error("body: inf coordinate", [] { return "v 0 inf 0\n" + cube_obj(1.0); },
             {"line 1", "not finite"});
  body_error("body: huge coordinate 1e999", [] { return "v 0 1e999 0\n" + cube_obj(1.0); },
             {"line 1", "1e999"});
  body_error("body: ESC in a vertex coordinate (quoted in the message)",
             [] { return "v 0 \x1b[2J 0\n" + cube_obj(1.0); }, {"line 1", "'\\x1b[2J'"});
  body_error("body: huge coordinates 1e150 (closed cube, volume overflows)",
             [] { return cube_obj(1e150); }, {"line ", "encloses no volume"});
  body_error("body: huge coordinates 1e300 (extent overflows)", [] { return cube_obj(1e300); },
             {""});
  body_error("body: non-manifold edge (three faces)",
             [] { return cube_obj(1.0) + "v 0 3 0\nf 1 2 9\n"; }, {"line ", "not a manifold"});
  body_error("body: vertex index 2^63",
             [] { return cube_obj(1.0) + "f 1 2 9223372036854775808\n"; },
             {"line 15", "no valid vertex index"});
  body_error("body: relative index before the first vertex",
             [] { return cube_obj(1.0) + "f -1 -2 -100\n"; }, {"line 15", "relative vertex index"});
  body_error("body: one face with 10^6 distinct corners",
             [] {
               std::string text;
               char line[96];
               for (int i = 0; i < 1000000; ++i) {
                 const double angle = 2.0 * std::numbers::pi * i / 1000000;
                 std::snprintf(line, sizeof line, "v %.9f %.9f 0\n", std::cos(angle),
                               std::sin(angle));
                 text += line;
               }
               text += "f";
               for (int i = 1; i <= 1000000; ++i)
                 text.append(" ").append(std::to_string(i));
               return text + "\n";
             },
             {"line 1000001", "degenerate face"});
  body_error("body: one face with 10^6 corners, repeating",
             [] {
               std::string text = cube_obj(1.0) + "f";
               for (int i = 0; i < 1000000; ++i)
                 text.append(" ").append(std::to_string(1 + i % 8));
               return text + "\n";
             },
             {"line 15", "appears twice"});
  all.push_back({"body: sphere of 10^6 vertices",
                 Kind::Body,
                 "body.obj",
                 [] { return sphere_obj(1001, 1000); },
                 {},
                 [](const Outcome& outcome) {
                   return outcome.message.find("1000002 vertices") != std::string::npos
                              ? std::string()
                              : "expected the sphere: " + outcome.message;
                 }});
  all.push_back({"body: non-UTF-8 file name, CRLF lines",
                 Kind::Body,
                 "body_\xff\xfe.obj",
                 [] {
                   std::string text = cube_obj(1.0), crlf;
                   for (char c : text)
                     crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
                   return crlf;
                 },
                 {},
                 [](const Outcome& outcome) {
                   return outcome.message.find("12 triangles") != std::string::npos
                              ? std::string()
                              : "expected the cube: " + outcome.message;
                 }});
  return all;
}

// Hostile paths: only regular files are read, and at most 256 MiB of them.
std::vector<HostileCase> hostile_cases() {
  std::vector<HostileCase> all;
  const auto hostile = [&](std::string name, Kind kind,
                           std::function<fs::path(const fs::path&)> make,
                           std::vector<std::string> fragments, bool budget_error) {
    all.push_back(
        {{std::move(name), kind, "", nullptr, std::move(fragments), nullptr, budget_error},
         std::move(make)});
  };
  const auto fifo = [](const fs::path& dir) {
    const fs::path path = dir / "fifo.json";
    ::mkfifo(path.c_str(), 0600);
    return path;
  };
  hostile(
      "pattern: /dev/zero", Kind::Pattern, [](const fs::path&) { return fs::path("/dev/zero"); },
      {"is a character device, not a regular file"}, false);
  hostile("pattern: a FIFO nobody writes to", Kind::Pattern, fifo,
          {"is a pipe (FIFO), not a regular file"}, false);
  hostile(
      "pattern: 256 MiB + 1 byte (sparse file of zeros)", Kind::Pattern,
      [](const fs::path& dir) {
        const fs::path path = dir / "p.json";
        std::ofstream(path).close();
        fs::resize_file(path, (std::uintmax_t{256} << 20) + 1);
        return path;
      },
      {"the file is larger than 256 MiB"}, true);
  hostile(
      "body: /dev/zero", Kind::Body, [](const fs::path&) { return fs::path("/dev/zero"); },
      {"is a character device, not a regular file"}, false);
  hostile("body: a FIFO nobody writes to", Kind::Body, fifo,
          {"is a pipe (FIFO), not a regular file"}, false);
  return all;
}

Outcome run(const Case& c, const fs::path& path) {
  Outcome outcome;
  try {
    if (c.kind == Kind::Pattern) {
      const Garment garment = build_garment(load_pattern(path));
      outcome.message = std::to_string(garment.pieces.size()) + " pieces, " +
                        std::to_string(garment.vertex_count()) + " vertices";
    } else {
      const BodyMesh body = load_body_obj(path);
      double volume = 0.0;
      for (int t = 0; t < body.triangles.rows(); ++t) {
        const Eigen::Vector3d a = body.vertices.row(body.triangles(t, 0));
        const Eigen::Vector3d b = body.vertices.row(body.triangles(t, 1));
        const Eigen::Vector3d cc = body.vertices.row(body.triangles(t, 2));
        volume += a.dot(b.cross(cc)) / 6.0;
      }
      char text[160];
      std::snprintf(text, sizeof text, "%lld vertices, %lld triangles, volume %+.3g m³",
                    static_cast<long long>(body.vertices.rows()),
                    static_cast<long long>(body.triangles.rows()), volume);
      outcome.message = text;
      if (volume > 0 && std::abs(volume - 1.0) < 1e-9) outcome.message += " (volume +1.000)";
    }
  } catch (const BudgetError& error) {
    outcome.error = true;
    outcome.message = std::string("[budget] ") + error.what();
  } catch (const InputError& error) {
    outcome.error = true;
    outcome.message = error.what();
  }
  return outcome;
}

// Runs the case in a child process killed after `seconds` (SIGALRM) and limited to
// kChildAddressSpace, and returns its outcome; `megabytes` receives the child's peak resident set.
Outcome run_isolated(const Case& c, const fs::path& path, double seconds, double& megabytes) {
  int channel[2];
  if (::pipe(channel) != 0) return {true, "pipe failed"};
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(channel[0]);
    ::alarm(static_cast<unsigned>(std::ceil(seconds)));
    if (!kAddressSanitizer) {
      const rlimit limit{kChildAddressSpace, kChildAddressSpace};
      ::setrlimit(RLIMIT_AS, &limit);
    }
    reset_peak_memory();
    const Outcome outcome = run(c, path);
    const std::string reply = std::string(outcome.error ? "E " : "R ") +
                              std::to_string(peak_memory_mb()) + "\n" + outcome.message;
    for (std::size_t sent = 0; sent < reply.size();) {
      const ssize_t count = ::write(channel[1], reply.data() + sent, reply.size() - sent);
      if (count <= 0) break;
      sent += static_cast<std::size_t>(count);
    }
    ::_exit(0);
  }
  ::close(channel[1]);
  std::string reply;
  char buffer[4096];
  for (ssize_t count; (count = ::read(channel[0], buffer, sizeof buffer)) > 0;)
    reply.append(buffer, static_cast<std::size_t>(count));
  ::close(channel[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  if (!WIFEXITED(status) || reply.size() < 2)
    return {true,
            "the child process died" +
                (WIFSIGNALED(status) ? " of signal " + std::to_string(WTERMSIG(status)) +
                                           (WTERMSIG(status) == SIGALRM ? " (time bound)" : "")
                                     : std::string())};
  const std::size_t end_of_line = reply.find('\n');
  megabytes = std::atof(reply.c_str() + 2);
  return {reply[0] == 'E', reply.substr(end_of_line + 1)};
}

// Whether `message` is printable ASCII (the test's own check, independent of the engine's
// escaping): no control character, no byte of a multi-byte or invalid sequence.
bool printable_ascii(const std::string& message) {
  return std::all_of(message.begin(), message.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte >= 0x20 && byte < 0x7f;
  });
}

std::string escape_cell(std::string text, std::size_t limit) {
  std::string out;
  for (unsigned char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else if (c < 0x20 || c >= 0x80)
      out += c >= 0x80 ? "?" : " ";  // the table stays ASCII even when names are not UTF-8
    else
      out += static_cast<char>(c);
  }
  if (out.size() > limit) out = out.substr(0, limit) + "…";
  return out;
}

}  // namespace

class TortureTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { QVERIFY(folder_.isValid()); }

  void torture_data() {
    QTest::addColumn<int>("index");
    const auto all = cases();
    for (std::size_t i = 0; i < all.size(); ++i)
      QTest::newRow(all[i].name.c_str()) << static_cast<int>(i);
    const auto hostile = hostile_cases();
    for (std::size_t i = 0; i < hostile.size(); ++i)
      QTest::newRow(hostile[i].expected.name.c_str()) << static_cast<int>(all.size() + i);
  }

  void torture() {
    QFETCH(int, index);
    const std::vector<Case> all = cases();
    const auto position = static_cast<std::size_t>(index);
    const bool hostile = position >= all.size();
    const HostileCase hostile_case =
        hostile ? hostile_cases()[position - all.size()] : HostileCase{all[position], nullptr};
    const Case& c = hostile_case.expected;
    const fs::path dir = fs::path(folder_.path().toStdString()) / ("case_" + std::to_string(index));
    fs::create_directories(dir);
    fs::path path = c.file_name.empty()  ? dir / "missing.json"
                    : c.file_name == "." ? dir
                                         : dir / c.file_name;
    std::size_t size = 0;
    if (c.content) {
      const std::string bytes = c.content();
      size = bytes.size();
      write_bytes(path, bytes);
    }
    if (hostile) {
      path = hostile_case.make(dir);
      std::error_code error;
      if (fs::is_regular_file(path, error)) size = fs::file_size(path, error);
    }
    const double time_bound = kCaseSeconds * test::time_scale();

    double megabytes = 0.0;
    const auto start = std::chrono::steady_clock::now();
    Outcome outcome;
    if (hostile) {
      outcome = run_isolated(c, path, time_bound, megabytes);
    } else {
      reset_peak_memory();
      outcome = run(c, path);
      megabytes = peak_memory_mb();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    Row row;
    row.name = c.name;
    row.kind = c.kind == Kind::Pattern ? "pattern" : "body";
    row.input = c.content || size > 0 ? human_size(size) : "—";
    row.outcome = outcome.error
                      ? (outcome.message.rfind("[budget]", 0) == 0 ? "refused (budget)" : "error")
                      : "result";
    row.message = outcome.message;
    row.seconds = seconds;
    row.megabytes = megabytes;
    qInfo("case | %s | %s | %.2f s | %.0f MiB | %s", c.name.c_str(), row.outcome.c_str(), seconds,
          megabytes, outcome.message.substr(0, 300).c_str());

    const auto record = [&](bool passed) {
      row.passed = passed;
      table().push_back(row);
    };
    std::string failure;
    if (c.check) {
      if (outcome.error)
        failure = "expected a result, got: " + outcome.message;
      else
        failure = c.check(outcome);
    } else if (!outcome.error) {
      failure = "expected an error, got a result: " + outcome.message;
    } else {
      std::string message = outcome.message;
      if (message.rfind("[budget] ", 0) == 0) message = message.substr(9);
      if (c.budget_error && outcome.message.rfind("[budget]", 0) != 0)
        failure = "expected a BudgetError: " + message;
      if (message.rfind(path.string(), 0) != 0)
        failure = "the message does not start with the file's path: " + message;
      for (const std::string& fragment : c.fragments)
        if (message.find(fragment) == std::string::npos)
          failure = "the message lacks \"" + fragment + "\": " + message;
      if (message.rfind(path.string(), 0) == 0 &&
          !printable_ascii(message.substr(path.string().size())))
        failure = "the message echoes raw bytes of the input: " + message;
    }
    if (failure.empty() && seconds > time_bound)
      failure = "took " + std::to_string(seconds) + " s, over " + std::to_string(time_bound) + " s";
    const double memory_bound = kCaseMegabytes * kMemoryScale;
    if (failure.empty() && megabytes > memory_bound)
      failure = "peak memory " + std::to_string(megabytes) + " MiB, over " +
                std::to_string(memory_bound) + " MiB";
    record(failure.empty());
    QVERIFY2(failure.empty(), failure.c_str());
  }

  void cleanupTestCase() {
    // QTemporaryDir removes through QString paths, which cannot name the cases' files whose
    // names are not UTF-8 (pattern_\xff\xfe.json): every run left its folder behind. The
    // bytes of std::filesystem can.
    std::error_code ignored;
    fs::remove_all(fs::path(folder_.path().toStdString()), ignored);
    writeTable();
  }

 private:
  void writeTable() {
    const char* output = std::getenv("GARMENT_ROBUSTNESS_TABLE");
    if (!output) return;
    std::ostringstream out;
    out << "| case | input | outcome | message (or result) | time | peak RSS | pass |\n"
        << "| --- | --- | --- | --- | --- | --- | --- |\n";
    const std::string prefix = folder_.path().toStdString();
    for (const Row& row : table()) {
      std::string message = row.message;
      // Temporary folder → <tmp>, so that the table is stable.
      for (std::size_t at; (at = message.find(prefix)) != std::string::npos;)
        message.replace(at, prefix.size(), "<tmp>");
      char numbers[64];
      std::snprintf(numbers, sizeof numbers, "%.2f s | %.0f MiB", row.seconds, row.megabytes);
      out << "| " << escape_cell(row.name, 200) << " | " << row.input << " | " << row.outcome
          << " | " << escape_cell(message, 220) << " | " << numbers << " | "
          << (row.passed ? "yes" : "**no**") << " |\n";
    }
    write_file_atomically(output, out.str());
  }

  QTemporaryDir folder_;
};

QTEST_GUILESS_MAIN(TortureTest)
#include "test_torture.moc"
