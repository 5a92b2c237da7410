// Garment OBJ export and import on real patterns (tests/data/patterns): one group per panel in
// file order, vt = the file's own panel coordinates, positions round-trip, import matches vertices
// by vt whatever their order, and every malformed or mismatched file is a clear InputError.

#include <QtTest>

#include <QTemporaryDir>
#include <algorithm>
#include <numeric>
#include <random>
#include <sstream>

#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/io/garment_obj.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/flat_placement.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

Garment test_garment(const char* file, double edge_length = 0.02) {
  MeshingOptions options;
  options.target_edge_length = edge_length;
  return build_garment(load_pattern(test::test_data(std::string("patterns/") + file)), options);
}

// The flat placement, bent a little so that no coordinate is special.
Eigen::MatrixX3d some_state(const Garment& garment) {
  Eigen::MatrixX3d positions = flat_placement(garment);
  for (Eigen::Index v = 0; v < positions.rows(); ++v)
    positions(v, 2) += 0.05 * std::sin(3.0 * positions(v, 0) + 2.0 * positions(v, 1));
  return positions;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines)
    text += line + "\n";
  return text;
}

// Expects parse_garment_obj to throw an InputError whose message contains every fragment.
void expect_error(const std::string& text, const Garment& garment,
                  const std::vector<std::string>& fragments) {
  try {
    parse_garment_obj(text, "test.obj", garment);
    QFAIL("no error");
  } catch (const InputError& error) {
    const std::string message = error.what();
    QVERIFY2(message.rfind("test.obj: ", 0) == 0, message.c_str());
    for (const std::string& fragment : fragments)
      QVERIFY2(message.find(fragment) != std::string::npos,
               (message + " lacks " + fragment).c_str());
  }
}

// Rewrites an exported OBJ with each group's vertices (and vt) in reverse order, groups in reverse
// order, and faces renumbered accordingly.
std::string shuffled_obj(const Garment& garment, const Eigen::MatrixX3d& positions) {
  std::vector<int> order(static_cast<std::size_t>(garment.vertex_count()));
  std::vector<int> file_index(order.size());
  std::size_t next = 0;
  for (auto piece = garment.pieces.rbegin(); piece != garment.pieces.rend(); ++piece)
    for (int v = piece->first_vertex + piece->vertex_count - 1; v >= piece->first_vertex; --v) {
      file_index[v] = static_cast<int>(next) + 1;
      order[next++] = v;
    }
  std::string text;
  for (int v : order)
    text += "v " + std::to_string(positions(v, 0)) + " " + std::to_string(positions(v, 1)) + " " +
            std::to_string(positions(v, 2)) + "\n";
  char uv[96];
  for (int v : order) {
    std::snprintf(uv, sizeof uv, "vt %.12g %.12g\n", garment.pattern_positions(v, 0),
                  garment.pattern_positions(v, 1));
    text += uv;
  }
  text += "vn 0 0 1\n";
  for (auto piece = garment.pieces.rbegin(); piece != garment.pieces.rend(); ++piece) {
    text += "g " + piece->name + "\nusemtl cloth\n";
    for (int t = piece->first_triangle; t < piece->first_triangle + piece->triangle_count; ++t) {
      text += "f";
      for (int k = 0; k < 3; ++k) {
        const std::string id = std::to_string(file_index[garment.triangles(t, k)]);
        text += " " + id + "/" + id + "/1";
      }
      text += "\n";
    }
  }
  return text;
}

}  // namespace

class GarmentObjTest : public QObject {
  Q_OBJECT

 private slots:
  void export_has_one_group_per_panel_and_pattern_uv_data() {
    QTest::addColumn<QString>("file");
    QTest::newRow("trousers with darts") << "gc_0005_specification.json";
    QTest::newRow("top with sleeve and cuffs") << "gc_0007_specification.json";
    QTest::newRow("right_wrong stitches, circle edges") << "gc_0339_specification.json";
    QTest::newRow("template, 300 units per metre") << "basic_tee__tee.json";
  }
  void export_has_one_group_per_panel_and_pattern_uv() {
    QFETCH(QString, file);
    const Garment garment = test_garment(file.toStdString().c_str());
    const Eigen::MatrixX3d positions = some_state(garment);
    const std::vector<std::string> lines = lines_of(format_garment_obj(garment, positions));
    std::vector<std::string> groups;
    int vertices = 0, uvs = 0, faces = 0;
    for (const std::string& line : lines) {
      if (line.rfind("g ", 0) == 0) groups.push_back(line.substr(2));
      if (line.rfind("v ", 0) == 0) {
        double x, y, z;
        QCOMPARE(std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z), 3);
        QVERIFY((Eigen::Vector3d(x, y, z) - positions.row(vertices).transpose()).norm() < 1e-8);
        ++vertices;
      }
      if (line.rfind("vt ", 0) == 0) {
        double u, w;
        QCOMPARE(std::sscanf(line.c_str(), "vt %lf %lf", &u, &w), 2);
        QVERIFY((Eigen::Vector2d(u, w) - garment.pattern_positions.row(uvs).transpose()).norm() <
                1e-5);
        ++uvs;
      }
      faces += line.rfind("f ", 0) == 0;
    }
    QCOMPARE(int(groups.size()), int(garment.pattern.panels.size()));
    for (std::size_t p = 0; p < groups.size(); ++p)
      QCOMPARE(groups[p], garment.pattern.panels[p].name);
    // Not welded: every piece keeps its own seam vertices.
    QCOMPARE(vertices, garment.vertex_count());
    QCOMPARE(uvs, garment.vertex_count());
    QCOMPARE(faces, garment.triangle_count());
  }

  void round_trip_keeps_positions_data() { export_has_one_group_per_panel_and_pattern_uv_data(); }
  void round_trip_keeps_positions() {
    QFETCH(QString, file);
    const Garment garment = test_garment(file.toStdString().c_str());
    const Eigen::MatrixX3d positions = some_state(garment);
    QTemporaryDir folder;
    const std::filesystem::path path = folder.filePath("garment.obj").toStdString();
    write_garment_obj(path, garment, positions);
    const Eigen::MatrixX3d read = read_garment_obj(path, garment);
    QVERIFY((read - positions).cwiseAbs().maxCoeff() < 1e-8);
    // Overwriting replaces the file as a whole.
    write_garment_obj(path, garment, 2.0 * positions);
    QVERIFY((read_garment_obj(path, garment) - 2.0 * positions).cwiseAbs().maxCoeff() < 1e-8);
    // No temporary file is left beside it.
    QCOMPARE(std::distance(std::filesystem::directory_iterator(path.parent_path()),
                           std::filesystem::directory_iterator()),
             std::ptrdiff_t{1});
  }

  void import_matches_vertices_by_vt_not_order() {
    const Garment garment = test_garment("gc_0339_specification.json");
    const Eigen::MatrixX3d positions = some_state(garment);
    const Eigen::MatrixX3d read =
        parse_garment_obj(shuffled_obj(garment, positions), "shuffled.obj", garment);
    QVERIFY((read - positions).cwiseAbs().maxCoeff() < 1e-5);
  }

  void foreign_group_is_named() {
    const Garment garment = test_garment("gc_0007_specification.json");
    std::vector<std::string> lines = lines_of(format_garment_obj(garment, flat_placement(garment)));
    const auto group = std::find_if(lines.begin(), lines.end(), [](const std::string& line) {
      return line.rfind("g ", 0) == 0;
    });
    *group = "g collar_of_another_pattern";
    expect_error(join(lines), garment,
                 {"line " + std::to_string(group - lines.begin() + 1), "collar_of_another_pattern",
                  "not a panel"});
  }

  void missing_group_is_named() {
    const Garment garment = test_garment("gc_0007_specification.json");
    const std::string missing = garment.pieces.back().name;
    std::vector<std::string> lines = lines_of(format_garment_obj(garment, flat_placement(garment)));
    // Drop the last group's faces (its vertices stay, unused).
    const auto group = std::find(lines.begin(), lines.end(), "g " + missing);
    lines.erase(std::remove_if(group, lines.end(),
                               [](const std::string& line) {
                                 return line.rfind("f ", 0) == 0 || line.rfind("g ", 0) == 0;
                               }),
                lines.end());
    expect_error(join(lines), garment, {"no group for the panels " + missing});
  }

  void garment_meshed_at_another_resolution_is_refused() {
    const Garment fine = test_garment("gc_0007_specification.json");
    const Garment coarse = test_garment("gc_0007_specification.json", 0.03);
    expect_error(format_garment_obj(fine, flat_placement(fine)), coarse,
                 {"group '" + coarse.pieces[0].name + "'", "vertices, but the panel meshed at 30"});
  }

  void malformed_lines_are_located() {
    const Garment garment = test_garment("gc_0007_specification.json");
    const std::vector<std::string> good =
        lines_of(format_garment_obj(garment, flat_placement(garment)));
    const auto first_line = [&](const char* prefix) {
      return static_cast<std::size_t>(
          std::find_if(good.begin(), good.end(),
                       [&](const std::string& line) { return line.rfind(prefix, 0) == 0; }) -
          good.begin());
    };
    const std::size_t v = first_line("v "), vt = first_line("vt "), f = first_line("f ");
    const auto with = [&](std::size_t index, const std::string& replacement) {
      std::vector<std::string> lines = good;
      lines[index] = replacement;
      return join(lines);
    };
    const auto at = [](std::size_t index) { return "line " + std::to_string(index + 1); };
    expect_error(with(v, "v 0.1 abc 0.2"), garment, {at(v), "abc is not a number"});
    expect_error(with(v, "v 0.1 0.2"), garment, {at(v), "a number is missing"});
    expect_error(with(v, "v nan 0 0"), garment, {at(v), "not finite"});
    expect_error(with(vt, "vt 1e999 0"), garment, {at(vt)});
    expect_error(with(f, "f 1 2 3"), garment, {at(f), "has no vt"});
    expect_error(with(f, "f 1//1 2//2 3//3"), garment, {at(f), "has no vt"});
    expect_error(with(f, "f 999999/1 2/2 3/3"), garment,
                 {at(f), "vertex index 999999 out of range"});
    expect_error(with(f, "f 1/0 2/2 3/3"), garment, {at(f), "vt index 0 out of range"});
    expect_error(with(f, "f 1/1 2/2"), garment, {at(f), "at least 3 corners"});
    expect_error(with(vt, "vt 12345.5 -999"), garment, {"(12345.5, -999) is not a mesh vertex"});
    // A face before the first group.
    std::vector<std::string> early = good;
    early.insert(early.begin(), "f 1/1 2/2 3/3");
    expect_error(join(early), garment, {"outside of any `g` group"});
  }

  void empty_file_names_every_panel() {
    const Garment garment = test_garment("gc_0000_specification.json");
    expect_error("", garment, {"no group for the panels " + garment.pieces[0].name});
  }

  // A group name with control characters is quoted escaped: the terminal shows \x1b, it does not
  // obey it.
  void control_characters_in_a_group_name_are_escaped() {
    const Garment garment = test_garment("gc_0007_specification.json");
    std::vector<std::string> lines = lines_of(format_garment_obj(garment, flat_placement(garment)));
    const auto group = std::find_if(lines.begin(), lines.end(), [](const std::string& line) {
      return line.rfind("g ", 0) == 0;
    });
    *group = "g \x1b[2Jcollar\x07";
    try {
      parse_garment_obj(join(lines), "test.obj", garment);
      QFAIL("no error");
    } catch (const InputError& error) {
      const std::string message = error.what();
      QVERIFY2(message.find("group '\\x1b[2Jcollar\\x07' is not a panel") != std::string::npos,
               message.c_str());
      QVERIFY2(message.find('\x1b') == std::string::npos, "a raw ESC in the message");
      QVERIFY2(message.find('\x07') == std::string::npos, "a raw BEL in the message");
    }
  }

  // The pattern reader refuses names that cannot stand on a `g` line; a garment whose names were
  // set otherwise is refused by the writer instead of being written with its indices shifted.
  void name_that_would_break_its_g_line_is_not_written_data() {
    QTest::addColumn<QByteArray>("name");
    QTest::newRow("newline") << QByteArray("front\nv 0 0 0");
    QTest::newRow("carriage return") << QByteArray("front\r");
    QTest::newRow("empty") << QByteArray();
    QTest::newRow("NUL") << QByteArray("fr\0ont", 6);
    QTest::newRow("ESC") << QByteArray("\x1b[2Jfront");
    QTest::newRow("leading space") << QByteArray(" front");
    QTest::newRow("invalid UTF-8") << QByteArray("fr\xffont");
  }
  void name_that_would_break_its_g_line_is_not_written() {
    QFETCH(QByteArray, name);
    Garment garment = test_garment("gc_0007_specification.json");
    garment.pieces[1].name = name.toStdString();
    try {
      format_garment_obj(garment, flat_placement(garment));
      QFAIL("written");
    } catch (const std::invalid_argument& error) {
      QVERIFY2(std::string(error.what()).find("piece 1 '") != std::string::npos, error.what());
    }
  }

  void unreadable_file_is_an_input_error() {
    const Garment garment = test_garment("gc_0000_specification.json");
    QVERIFY_THROWS_EXCEPTION(InputError, read_garment_obj("/nonexistent/garment.obj", garment));
  }
};

QTEST_APPLESS_MAIN(GarmentObjTest)
#include "test_garment_obj.moc"
