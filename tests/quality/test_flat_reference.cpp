// The flat placement of real patterns (the state GarmentCode's simulator starts from) and the
// quality check on it with the real bodies; `garment-init flat` and `check` end to end. Tests that
// need the shared bodies skip when the dataset is absent.

#include <QtTest>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <numbers>

#include "engine/body/body_mesh.h"
#include "engine/core/atomic_file.h"
#include "engine/core/input_file.h"
#include "engine/core/mesh_geometry.h"
#include "engine/io/garment_obj.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/flat_placement.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"
#include "quality/constructed_garment.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

const char* const kGarmentCodeFiles[] = {"gc_0000_specification.json", "gc_0005_specification.json",
                                         "gc_0007_specification.json", "gc_0012_specification.json",
                                         "gc_0339_specification.json"};

Garment test_garment(const std::string& file) {
  return build_garment(load_pattern(test::test_data("patterns/" + file)));
}

// The body GarmentCode made the pattern for (index.json → body_obj), from the shared dataset.
std::filesystem::path body_of(const std::string& file) {
  const std::string text = read_file(test::shared_data("patterns/garmentcode_random/index.json"));
  const QJsonArray files =
      QJsonDocument::fromJson(QByteArray::fromStdString(text)).object()["files"].toArray();
  for (const auto& entry : files)
    if (entry.toObject()["file"].toString().toStdString() == file)
      return test::shared_data("bodies/" + entry.toObject()["body_obj"].toString().toStdString() +
                               ".obj");
  return {};
}

Eigen::Matrix3d rotation_from_angle_axes(const Eigen::Vector3d& degrees) {
  const Eigen::Vector3d r = degrees * std::numbers::pi / 180.0;
  return (Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

struct Run {
  int exit_code = -1;
  QByteArray out, err;
};

Run garment_init(const QStringList& arguments) {
  QProcess process;
  process.start(GARMENT_INIT_EXE, arguments);
  Run run;
  if (!process.waitForFinished(120000)) return run;
  run.exit_code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
  run.out = process.readAllStandardOutput();
  run.err = process.readAllStandardError();
  return run;
}

QString path_text(const std::filesystem::path& path) {
  return QString::fromStdString(path.string());
}

// Two rectangles (front, back) of half the circumference of a 25 cm radius tube, sewn side to side.
constexpr const char* kTubePattern = R"({
  "pattern": {
    "panels": {
      "front": {"vertices": [[0, 0], [78.5398, 0], [78.5398, 40], [0, 40]],
                "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                          {"endpoints": [3, 0]}],
                "rotation": [0, 0, 0], "translation": [-39.27, 100, 25]},
      "back": {"vertices": [[0, 0], [78.5398, 0], [78.5398, 40], [0, 40]],
               "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                         {"endpoints": [3, 0]}],
               "rotation": [0, 0, 0], "translation": [-39.27, 100, -25]}
    },
    "panel_order": ["front", "back"],
    "stitches": [[{"panel": "front", "edge": 1}, {"panel": "back", "edge": 3}],
                 [{"panel": "back", "edge": 1}, {"panel": "front", "edge": 3}]]
  },
  "properties": {"curvature_coords": "relative", "normalize_panel_translation": false,
                 "units_in_meter": 100, "normalized_edge_loops": true},
  "parameters": {}, "parameter_order": []
})";

}  // namespace

class FlatReferenceTest : public QObject {
  Q_OBJECT

 private slots:
  void flat_placement_is_the_files_transform_data() {
    QTest::addColumn<QString>("file");
    for (const char* file : kGarmentCodeFiles)
      QTest::newRow(file) << file;
    QTest::newRow("basic_tee__tee.json") << "basic_tee__tee.json";
    QTest::newRow("skirts__skirt_4_panels.json") << "skirts__skirt_4_panels.json";
  }
  void flat_placement_is_the_files_transform() {
    QFETCH(QString, file);
    const Garment garment = test_garment(file.toStdString());
    const Eigen::MatrixX3d positions = flat_placement(garment);
    const Eigen::MatrixX3d normals = triangle_normals(positions, garment.triangles);
    for (const Piece& piece : garment.pieces) {
      const Panel& panel = garment.pattern.panels[piece.panel];
      const Eigen::Matrix3d rotation = rotation_from_angle_axes(panel.rotation_degrees);
      for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
        const Eigen::Vector3d local(garment.pattern_positions(v, 0),
                                    garment.pattern_positions(v, 1), 0.0);
        const Eigen::Vector3d expected =
            rotation * local / garment.pattern.units_in_meter + panel.translation;
        QVERIFY((positions.row(v).transpose() - expected).norm() < 1e-9);
      }
      // Unsimulated: every triangle lies flat, facing the outside the file's loop winding gives
      // (README: Rot · (0, 0, sign of the signed area); clockwise loops are the mirrored ones).
      const Eigen::Vector3d outside =
          rotation * Eigen::Vector3d(0, 0, piece.frame.mirrored ? -1 : 1);
      for (int t = piece.first_triangle; t < piece.first_triangle + piece.triangle_count; ++t)
        QVERIFY2(normals.row(t).dot(outside) > 1.0 - 1e-9, piece.name.c_str());
    }
  }

  void left_and_right_pieces_lie_on_their_side() {
    for (const char* file : kGarmentCodeFiles) {
      const Garment garment = test_garment(file);
      const Eigen::MatrixX3d centroids = piece_centroids(garment, flat_placement(garment));
      for (const Piece& piece : garment.pieces) {
        const ExpectedRegion region = expected_region_from_name(piece.name);
        if (region.left_right == LeftRight::Left)
          QVERIFY2(centroids(piece.panel, 0) > 0.0, piece.name.c_str());
        if (region.left_right == LeftRight::Right)
          QVERIFY2(centroids(piece.panel, 0) < 0.0, piece.name.c_str());
      }
    }
  }

  void check_on_the_flat_placement_with_the_real_body() {
    if (!test::shared_data_available()) QSKIP("shared dataset absent");
    for (const char* file : kGarmentCodeFiles) {
      const Garment garment = test_garment(file);
      const BodyMesh body = load_body_obj(body_of(file));
      const BodyReference reference(body);
      const Eigen::MatrixX3d positions = flat_placement(garment);
      // Around the body: the garment's height range overlaps the body's (feet at y = 0 in both).
      const double low = positions.col(1).minCoeff(), high = positions.col(1).maxCoeff();
      QVERIFY2(low < body.upper_corner().y() && high > 0.3 * body.height(), file);
      const GarmentMetrics metrics =
          measure_garment(garment, positions, &reference, expected_regions_from_names(garment));
      QVERIFY2(metrics.misplaced.empty(), file);
      QCOMPARE(metrics.folds, 0);
      QVERIFY(std::abs(metrics.theta_in - 1.0) < 1e-9);
      QVERIFY(metrics.max_strain < 1e-9);
      QVERIFY(metrics.max_seam_gap_m > 0.005);
      const QualityVerdict verdict = judge_garment(garment, metrics);
      QVERIFY(verdict.failed(FailureKind::SeamGap));
      QVERIFY(!verdict.failed(FailureKind::Misplaced));
      QVERIFY(!verdict.failed(FailureKind::Fold));
      QVERIFY(!verdict.failed(FailureKind::Strain));
    }
  }

  void inside_count_matches_a_test_of_every_vertex() {
    if (!test::shared_data_available()) QSKIP("shared dataset absent");
    const Garment garment = test_garment("gc_0007_specification.json");
    const BodyMesh body = load_body_obj(body_of("gc_0007_specification.json"));
    const BodyReference reference(body);
    // The flat top pushed 20 cm back: its front pieces cut through the torso.
    Eigen::MatrixX3d positions = flat_placement(garment);
    positions.col(2).array() -= 0.2;
    const GarmentMetrics metrics =
        measure_garment(garment, positions, &reference, expected_regions_from_names(garment));
    int inside = 0;
    double depth = 0.0;
    for (int v = 0; v < garment.vertex_count(); ++v)
      if (reference.surface.strictly_inside(positions.row(v).transpose())) {
        ++inside;
        depth =
            std::max(depth, reference.surface.distance_to_surface(positions.row(v).transpose()));
      }
    QVERIFY(inside > 50);
    QCOMPARE(metrics.body_inside_vertices, inside);
    QCOMPARE(metrics.max_inside_depth_m, depth);
    QVERIFY(metrics.body_crossing_edges > 0);
    QVERIFY(judge_garment(garment, metrics).failed(FailureKind::BodyPenetration));
  }

  void body_axes_of_the_real_bodies() {
    if (!test::shared_data_available()) QSKIP("shared dataset absent");
    for (const char* name : {"mean_all", "f_smpl_average_A40", "m_smpl_average_A40"}) {
      const BodyMesh body =
          load_body_obj(test::shared_data(std::string("bodies/") + name + ".obj"));
      const BodyAxes axes = body_axes(body);
      QVERIFY(std::abs(axes.mid_x) < 0.02);
      for (bool left : {true, false}) {
        const AxisLine& arm = axes.arm(left);
        // A-pose: the arm runs outwards and down; its axis passes through the hand (the outermost
        // vertex) and, extended, near the shoulder, well away from the torso's centre line.
        QVERIFY(arm.direction.x() * (left ? 1 : -1) > 0.5);
        QVERIFY(arm.direction.y() < -0.3);
        Eigen::Index outermost = 0;
        if (left)
          body.vertices.col(0).maxCoeff(&outermost);
        else
          body.vertices.col(0).minCoeff(&outermost);
        QVERIFY(arm.distance(body.vertices.row(outermost).transpose()) < 0.08);
        const double shoulder_y = 0.82 * body.height();
        const Eigen::Vector3d at_shoulder =
            arm.point + (shoulder_y - arm.point.y()) / arm.direction.y() * arm.direction;
        QVERIFY2(std::abs(at_shoulder.x()) > 0.08 && std::abs(at_shoulder.x()) < 0.3, name);
      }
      // Front/back centre at chest height lies inside the body's depth.
      const double chest_z = axes.centre_z(0.72 * body.height());
      QVERIFY(chest_z > body.lower_corner().z() && chest_z < body.upper_corner().z());
    }
  }

  void command_line_flat_then_check() {
    if (!test::shared_data_available()) QSKIP("shared dataset absent");
    QTemporaryDir folder;
    const QString pattern = path_text(test::test_data("patterns/gc_0007_specification.json"));
    const QString body = path_text(body_of("gc_0007_specification.json"));
    const QString flat = folder.filePath("flat.obj");
    Run run = garment_init({"flat", pattern, "-o", flat});
    QCOMPARE(run.exit_code, 0);
    const Garment garment = test_garment("gc_0007_specification.json");
    QVERIFY((read_garment_obj(flat.toStdString(), garment) - flat_placement(garment))
                .cwiseAbs()
                .maxCoeff() < 1e-8);

    run = garment_init({"check", flat, "--pattern", pattern, "--body", body, "--json"});
    QCOMPARE(run.exit_code, 3);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    for (const char* key :
         {"body_inside_vertices", "body_crossing_edges", "self_crossing_edges", "folds",
          "max_strain", "p99_strain", "max_seam_gap_m", "misplaced", "fails", "ok"})
      QVERIFY2(report.contains(key), key);
    QCOMPARE(report["ok"].toBool(), false);
    QCOMPARE(report["fails"].toArray()[0].toObject()["kind"].toString(), QString("seam_gap"));
    QVERIFY(report["max_seam_gap_m"].toDouble() > 0.005);

    run = garment_init({"check", flat, "--pattern", pattern, "--body", body});
    QCOMPARE(run.exit_code, 3);
    QVERIFY(run.out.contains("max_seam_gap_m"));
    QVERIFY(run.out.contains("ok                     false"));

    // Without --body: the bundled body.
    run = garment_init({"check", flat, "--pattern", pattern});
    QCOMPARE(run.exit_code, 3);
    QVERIFY(run.out.contains("mean_all.obj"));

    // The OBJ of one pattern checked against another: bad input, the group named.
    run = garment_init({"check", flat, "--pattern",
                        path_text(test::test_data("patterns/gc_0000_specification.json")), "--body",
                        body});
    QCOMPARE(run.exit_code, 1);
    QVERIFY2(run.err.contains("is not a panel of"), run.err.constData());
    run = garment_init({"check", flat, "--body", body});
    QCOMPARE(run.exit_code, 2);
    run = garment_init({"check", flat, "--pattern", pattern, "--body", "/nonexistent/body.obj"});
    QCOMPARE(run.exit_code, 1);
  }

  void command_line_check_passes_a_clean_garment() {
    QTemporaryDir folder;
    const std::filesystem::path pattern = folder.filePath("tube.json").toStdString();
    const std::filesystem::path body = folder.filePath("cylinder.obj").toStdString();
    const std::filesystem::path garment_path = folder.filePath("tube.obj").toStdString();
    write_file_atomically(pattern, kTubePattern);
    write_file_atomically(body, test::body_obj_text(test::cylinder_body()));
    const Garment garment = build_garment(load_pattern(pattern));
    Eigen::MatrixX3d positions(garment.vertex_count(), 3);
    test::wrap_on_cylinder(garment, 0, 0.25, 0.0, 1.0, positions);
    test::wrap_on_cylinder(garment, 1, 0.25, std::numbers::pi, 1.0, positions);
    write_garment_obj(garment_path, garment, positions);
    Run run = garment_init({"check", path_text(garment_path), "--pattern", path_text(pattern),
                            "--body", path_text(body), "--json"});
    QVERIFY2(run.exit_code == 0, run.out.constData());
    QCOMPARE(QJsonDocument::fromJson(run.out).object()["ok"].toBool(), true);

    // The same tube turned half a turn: the front behind the body, exit 3.
    positions.col(0) *= -1.0;
    positions.col(2) *= -1.0;
    write_garment_obj(garment_path, garment, positions);
    run = garment_init({"check", path_text(garment_path), "--pattern", path_text(pattern), "--body",
                        path_text(body), "--json"});
    QCOMPARE(run.exit_code, 3);
    const QJsonArray misplaced = QJsonDocument::fromJson(run.out).object()["misplaced"].toArray();
    QCOMPARE(misplaced.size(), 2);
    QCOMPARE(misplaced[0].toObject()["piece"].toString(), QString("front"));
  }
};

QTEST_GUILESS_MAIN(FlatReferenceTest)
#include "test_flat_reference.moc"
