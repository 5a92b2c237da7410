// Body OBJ import: the real bodies load as closed outward meshes in metres; every kind of bad file
// is rejected with a message naming the file and the line; a body turned the wrong way or holding
// two copies of itself loads with a warning.

#include <QtTest>

#include <Eigen/Geometry>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/body/body_mesh.h"
#include "engine/body/body_warnings.h"
#include "engine/body/default_body.h"
#include "engine/core/error.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

double signed_volume(const BodyMesh& mesh) {
  double volume = 0.0;
  for (int t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(t, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(t, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(t, 2));
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

// Every directed edge appears once and its reverse once: closed and consistently oriented.
bool closed_and_consistent(const BodyMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (int t = 0; t < mesh.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      ++directed[{mesh.triangles(t, k), mesh.triangles(t, (k + 1) % 3)}];
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    const auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The OBJ with every vertex (x, y, z) written as (a x + b z, y, c x + d z): turned about y.
std::string turned_obj(const std::string& obj, double a, double b, double c, double d) {
  std::istringstream in(obj);
  std::ostringstream out;
  out.precision(9);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) {
      double x, y, z;
      std::istringstream(line.substr(2)) >> x >> y >> z;
      out << "v " << a * x + b * z << " " << y << " " << c * x + d * z << "\n";
    } else {
      out << line << "\n";
    }
  }
  return out.str();
}

// The OBJ twice in one file: its vertices again, moved by `offset` m along x, and its faces again
// on those vertices (`vertex_count` in the file).
std::string doubled_obj(const std::string& obj, int vertex_count, double offset) {
  std::istringstream in(obj);
  std::ostringstream vertices, faces;
  vertices.precision(9);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      double x, y, z;
      words >> x >> y >> z;
      vertices << "v " << x + offset << " " << y << " " << z << "\n";
    } else if (kind == "f") {
      faces << "f";
      for (std::string corner; words >> corner;)
        faces << " " << std::stoi(corner) + vertex_count;  // "12/5/3" counts as vertex 12
      faces << "\n";
    }
  }
  return obj + "\n" + vertices.str() + faces.str();
}

}  // namespace

class BodyImportTest : public QObject {
  Q_OBJECT

 private slots:
  void bundled_body_loads() {
    const BodyMesh body = load_body_obj(default_body_path());
    QCOMPARE(body.vertices.rows(), 23752);
    QCOMPARE(body.triangles.rows(), 47500);
    QCOMPARE(body.unit_scale, 1.0);
    QVERIFY(std::abs(body.height() - 1.72) < 0.01);
    QVERIFY(closed_and_consistent(body));
    QVERIFY(signed_volume(body) > 0.05);  // about 70 litres, outward
  }

  void shared_bodies_load() {
    if (!test::shared_data_available()) QSKIP("shared data folder absent");
    struct Expected {
      const char* name;
      int vertices, triangles;
      double height;
    };
    // SMPL bodies are 6,876 quads + 24 triangles; their header says centimetres, their numbers
    // are metres.
    for (const Expected& expected : {Expected{"mean_all", 23752, 47500, 1.720},
                                     Expected{"mean_all_apart", 23752, 47500, 1.714},
                                     Expected{"f_smpl_average_A40", 6890, 13776, 1.658},
                                     Expected{"m_smpl_average_A40", 6890, 13776, 1.791}}) {
      const BodyMesh body =
          load_body_obj(test::shared_data(std::string("bodies/") + expected.name + ".obj"));
      QCOMPARE(body.vertices.rows(), expected.vertices);
      QCOMPARE(body.triangles.rows(), expected.triangles);
      QCOMPARE(body.unit_scale, 1.0);
      QVERIFY2(std::abs(body.height() - expected.height) < 0.002, expected.name);
      QVERIFY2(closed_and_consistent(body), expected.name);
      QVERIFY2(signed_volume(body) > 0.04, expected.name);
    }
  }

  // Issue 40: both loaded without a word. The body, turned by 180° and by 90° about y, and in two
  // overlapping copies (the second 1 cm to the side), against itself as it is.
  void body_facing_minus_z_is_warned_about() {
    const std::string obj = read_text(test::test_data("bodies/f_smpl_average_A40.obj"));
    QVERIFY(body_warnings(parse_body_obj(obj, "upright.obj")).empty());
    const std::vector<std::string> back =
        body_warnings(parse_body_obj(turned_obj(obj, -1, 0, 0, -1), "back.obj"));
    QCOMPARE(back.size(), std::size_t{1});
    QVERIFY2(
        back[0].starts_with("back.obj: the body faces -z (") &&
            back[0].find("turn the body by 180° about the vertical (y) axis") != std::string::npos,
        back[0].c_str());
    // x' = z, z' = -x: the front, +z, turned to +x.
    const std::vector<std::string> side =
        body_warnings(parse_body_obj(turned_obj(obj, 0, 1, -1, 0), "side.obj"));
    QCOMPARE(side.size(), std::size_t{1});
    QVERIFY2(side[0].starts_with("side.obj: the body faces +x ("), side[0].c_str());
  }

  void two_copies_of_a_body_are_warned_about() {
    const std::string obj = read_text(test::test_data("bodies/f_smpl_average_A40.obj"));
    const std::vector<std::string> warnings =
        body_warnings(parse_body_obj(doubled_obj(obj, 6890, 0.01), "twice.obj"));
    QCOMPARE(warnings.size(), std::size_t{1});
    QVERIFY2(warnings[0].starts_with("twice.obj: vertices 1 and 6891: two overlapping closed "
                                     "surfaces of 13776 and 13776 triangles"),
             warnings[0].c_str());
  }

  // No false alarm on the real bodies, nor on a cube (no feet, one surface).
  void real_bodies_have_no_warnings() {
    std::vector<std::filesystem::path> bodies{default_body_path(),
                                              test::test_data("bodies/m_smpl_average_A40.obj"),
                                              test::test_data("bodies/cube_cm_inside_out.obj")};
    if (test::shared_data_available())
      bodies.push_back(test::shared_data("bodies/mean_all_apart.obj"));
    for (const std::filesystem::path& body : bodies) {
      const std::vector<std::string> warnings = body_warnings(load_body_obj(body));
      QVERIFY2(warnings.empty(), warnings.empty() ? "" : warnings.front().c_str());
    }
  }

  void centimetre_quads_inside_out_become_metre_triangles_outward() {
    const BodyMesh cube = load_body_obj(test::test_data("bodies/cube_cm_inside_out.obj"));
    QCOMPARE(cube.unit_scale, 0.01);
    QCOMPARE(cube.triangles.rows(), 12);
    QVERIFY(std::abs(cube.height() - 1.0) < 1e-12);
    QVERIFY(closed_and_consistent(cube));
    QVERIFY(std::abs(signed_volume(cube) - 1.0) < 1e-9);  // 1 m³, positive: outward
  }

  void bad_bodies_are_rejected_with_file_and_line_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("place");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << "empty.obj"
                           << ""
                           << "no vertices";
    QTest::newRow("bad index") << "bad_index.obj"
                               << "line 9"
                               << "vertex index 9 is out of range";
    QTest::newRow("zero index") << "zero_index.obj"
                                << "line 6"
                                << "vertex index 0 is invalid";
    QTest::newRow("degenerate") << "degenerate.obj"
                                << "line 11"
                                << "degenerate face";
    QTest::newRow("open") << "open.obj"
                          << "line "
                          << "not closed: 3 edge(s)";
    QTest::newRow("nan") << "nan.obj"
                         << "line 4"
                         << "not finite";
    QTest::newRow("non-manifold") << "non_manifold.obj"
                                  << "line "
                                  << "shared by 4 faces";
    QTest::newRow("not a number") << "not_a_number.obj"
                                  << "line 2"
                                  << "'zero' is not a number";
  }
  void bad_bodies_are_rejected_with_file_and_line() {
    QFETCH(QString, file);
    QFETCH(QString, place);
    QFETCH(QString, message);
    const std::filesystem::path path = test::test_data("bodies/bad") / file.toStdString();
    try {
      load_body_obj(path);
      QFAIL("accepted a bad body");
    } catch (const InputError& error) {
      const QString text = QString::fromStdString(error.what());
      QVERIFY2(text.startsWith(QString::fromStdString(path.string())), qPrintable(text));
      QVERIFY2(text.contains(place), qPrintable(text));
      QVERIFY2(text.contains(message), qPrintable(text));
    }
  }

  void missing_file_is_an_input_error() {
    QVERIFY_THROWS_EXCEPTION(InputError, load_body_obj(test::test_data("bodies/no_such.obj")));
  }

  void in_memory_mesh_is_validated_and_oriented() {
    BodyMesh tetrahedron;
    tetrahedron.source = "tetrahedron";
    tetrahedron.vertices.resize(4, 3);
    tetrahedron.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    tetrahedron.triangles.resize(4, 3);
    tetrahedron.triangles << 0, 1, 2, 0, 3, 1, 1, 3, 2, 0, 2, 3;  // all inward
    validate_and_orient_body(tetrahedron);
    QVERIFY(signed_volume(tetrahedron) > 0.0);
    QVERIFY(closed_and_consistent(tetrahedron));

    BodyMesh open = tetrahedron;
    open.triangles.conservativeResize(3, 3);
    QVERIFY_THROWS_EXCEPTION(InputError, validate_and_orient_body(open));
  }
};

QTEST_GUILESS_MAIN(BodyImportTest)
#include "test_import.moc"
