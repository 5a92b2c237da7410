// Landmarks and the 15 seed locations, found by cross-section analysis on every body, checked
// against anatomy and against each body's own measurement file; the JSON override.

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "engine/body/body.h"
#include "engine/body/body_cross_sections.h"
#include "engine/body/default_body.h"
#include "engine/body/location_overrides.h"
#include "engine/core/error.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

struct NamedBody {
  std::string name;
  std::filesystem::path obj, yaml;
};

std::vector<NamedBody> bodies() {
  std::vector<NamedBody> list = {{"mean_all (bundled)", default_body_path(),
                                  resource_directory() / "bodies" / "mean_all.yaml"}};
  if (test::shared_data_available())
    for (const char* name : {"mean_all_apart", "f_smpl_average_A40", "m_smpl_average_A40"}) {
      const std::string yaml = std::string(name) == "mean_all_apart" ? "mean_all" : name;
      list.push_back({name, test::shared_data(std::string("bodies/") + name + ".obj"),
                      test::shared_data("bodies/" + yaml + ".yaml")});
    }
  return list;
}

// The `body:` measurements of a GarmentCode body file (centimetres).
std::map<std::string, double> measurements(const std::filesystem::path& yaml) {
  std::ifstream in(yaml);
  std::map<std::string, double> values;
  const std::regex entry(R"(^\s+([a-z_]+):\s*([-0-9.]+))");
  std::smatch match;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, match, entry)) values[match[1]] = std::stod(match[2]);
  return values;
}

}  // namespace

class BodyLocationsTest : public QObject {
  Q_OBJECT

 private slots:
  void landmarks_are_in_anatomical_order() {
    for (const NamedBody& named : bodies()) {
      const BodyMesh mesh = load_body_obj(named.obj);
      const BodyLandmarks m = find_body_landmarks(mesh, BodySlicer(mesh));
      const QString what = QString("%1: crotch %2 hips %3 waist %4 bust %5 armpits %6 neck %7")
                               .arg(QString::fromStdString(named.name))
                               .arg(m.crotch)
                               .arg(m.hips)
                               .arg(m.waist)
                               .arg(m.bust)
                               .arg(m.armpits)
                               .arg(m.neck);
      qInfo().noquote() << what;
      QVERIFY2(m.floor < m.crotch && m.crotch < m.hips && m.hips < m.waist && m.waist < m.bust &&
                   m.bust < m.armpits && m.armpits < m.neck && m.neck < m.top,
               qPrintable(what));
    }
  }

  // The tape measure (convex hull perimeter of the torso's horizontal section) at the waist, bust
  // and hip heights, against the body's own measurement file. One known disagreement: the male
  // SMPL file gives waist 80 cm, a design value below every horizontal torso section of that
  // mesh (its narrowest, 92.5 cm at 1.155 m, is what is found); there the test checks that the
  // waist found is the narrowest section instead. The file is the odd one, not the landmark:
  // - where the file itself puts the waist (waist_line: 44.2 cm below the nape, the base of the
  //   neck at 1.520 m, so about 1.08 m) the section measures 95.0 cm, farther still from 80;
  // - no section between hips and bust is below 92.5 cm (checked below), so no waist height
  //   could give 80 cm within the 10 %;
  // - the file's bust and hips agree with the mesh within 4 % (100 vs 104.1 and 103.0 cm), and
  //   its waist repeats the female file's 80 (as its arm_length repeats 80): a template value;
  // - the landmark sits where it does on the three other bodies, at 62 % (female 62 %, mean_all
  //   65 %) of the way from crotch to armpits, whose files it matches within 1.5 %.
  void circumferences_match_the_measurement_files() {
    for (const NamedBody& named : bodies()) {
      const BodyMesh mesh = load_body_obj(named.obj);
      const BodySlicer slicer(mesh);
      const BodyLandmarks marks = find_body_landmarks(mesh, slicer);
      const std::map<std::string, double> yaml = measurements(named.yaml);
      for (const auto& [name, height] : {std::pair<std::string, double>{"waist", marks.waist},
                                         {"bust", marks.bust},
                                         {"hips", marks.hips}}) {
        QVERIFY2(yaml.count(name), qPrintable(QString::fromStdString(named.yaml.string())));
        const double measured = 100.0 * torso_girth(slicer, marks.centre_x, height);
        const double expected = yaml.at(name);
        const QString what = QString("%1 %2: %3 cm at %4 m, file %5 cm")
                                 .arg(QString::fromStdString(named.name))
                                 .arg(QString::fromStdString(name))
                                 .arg(measured)
                                 .arg(height)
                                 .arg(expected);
        qInfo().noquote() << what;
        if (named.name == "m_smpl_average_A40" && name == "waist") {
          for (double y = marks.hips; y <= marks.bust; y += 0.005)
            QVERIFY2(100.0 * torso_girth(slicer, marks.centre_x, y) >= measured - 0.01,
                     qPrintable(what));
          continue;
        }
        QVERIFY2(std::abs(measured - expected) <= 0.10 * expected, qPrintable(what));
      }
    }
  }

  void locations_are_named_sided_and_shaped() {
    for (const NamedBody& named : bodies()) {
      SignedDistanceOptions options;
      options.spacing = 0.02;  // the field is not what this test is about
      const Body body = load_body(named.obj, options);
      QCOMPARE(body.locations.size(), kBodyLocationNames.size());
      const BodyLandmarks& m = body.landmarks;
      const auto torso_centre_z = [&](double y) {
        return m.torso.origin.z() +
               (y - m.torso.origin.y()) * m.torso.direction.z() / m.torso.direction.y();
      };
      for (std::size_t l = 0; l < kBodyLocationNames.size(); ++l) {
        const BodyLocation& location = body.locations[l];
        const QString what = QString("%1 %2 at (%3, %4, %5)")
                                 .arg(QString::fromStdString(named.name))
                                 .arg(QString::fromStdString(location.name))
                                 .arg(location.center.x())
                                 .arg(location.center.y())
                                 .arg(location.center.z());
        QCOMPARE(location.name, std::string(kBodyLocationNames[l]));
        QVERIFY2(location.center.allFinite() && std::abs(location.axis.norm() - 1.0) < 1e-9,
                 qPrintable(what));
        QVERIFY2(location.center.y() > m.crotch && location.center.y() < m.top, qPrintable(what));
        const bool cylinder = location.surface == LocationSurface::cylinder;
        QCOMPARE(cylinder,
                 location.name == "neck" || location.name == "waist" || location.name == "pelvis");
        if (cylinder) {
          QVERIFY2(location.axis.y() > 0.8, qPrintable(what));  // up
          QVERIFY2(location.radius > 0.04 && location.radius < 0.3, qPrintable(what));
          QVERIFY2(std::abs(location.center.x() - m.centre_x) < 0.03, qPrintable(what));
        } else {
          QVERIFY2(location.half_width > 0.02 && location.half_height > 0.02, qPrintable(what));
          QVERIFY2(std::abs(location.axis.y()) < 0.2, qPrintable(what));  // faces sideways
          QVERIFY2(std::abs(location.up.dot(location.axis)) < 1e-9, qPrintable(what));
          // The plane touches the body and does not cut it at its centre.
          QVERIFY2(body.distance.grid.value(location.center) > -0.01, qPrintable(what));
        }
        const std::string& name = location.name;
        if (name.find("_left") != std::string::npos)
          QVERIFY2(location.center.x() > m.centre_x + 0.02, qPrintable(what));
        if (name.find("_right") != std::string::npos)
          QVERIFY2(location.center.x() < m.centre_x - 0.02, qPrintable(what));
        if (name.find("_front") != std::string::npos) {
          QVERIFY2(location.center.z() > torso_centre_z(location.center.y()), qPrintable(what));
          QVERIFY2(location.axis.z() > 0.9, qPrintable(what));
        }
        if (name.find("_back") != std::string::npos) {
          QVERIFY2(location.center.z() < torso_centre_z(location.center.y()), qPrintable(what));
          QVERIFY2(location.axis.z() < -0.9, qPrintable(what));
        }
      }
      QVERIFY(std::abs(body.location("waist").center.y() - m.waist) < 1e-9);
      QVERIFY(std::abs(body.location("neck").center.y() - m.neck) < 0.03);
      // A cylinder encloses its section: the body at its radius is outside.
      const BodyLocation& waist = body.location("waist");
      QVERIFY(waist.radius > 0.5 * torso_girth(BodySlicer(body.mesh), m.centre_x, m.waist) / M_PI);
    }
  }

  void axes_follow_the_a_pose() {
    for (const NamedBody& named : bodies()) {
      const BodyMesh mesh = load_body_obj(named.obj);
      const BodyLandmarks m = find_body_landmarks(mesh, BodySlicer(mesh));
      const QString what = QString::fromStdString(named.name);
      QVERIFY2(m.torso.direction.y() > 0.99, qPrintable(what));
      // Arms hang down and out at 35–60° from the vertical; legs almost straight down.
      for (const auto& [arm, side] : {std::pair{m.left_arm, 1.0}, std::pair{m.right_arm, -1.0}}) {
        QVERIFY2(arm.direction.y() < 0.0 && side * arm.direction.x() > 0.0, qPrintable(what));
        const double from_vertical = std::acos(-arm.direction.y()) * 180.0 / M_PI;
        QVERIFY2(from_vertical > 35.0 && from_vertical < 60.0, qPrintable(what));
        QVERIFY2(side * arm.origin.x() > 0.1 && arm.length > 0.4, qPrintable(what));
      }
      for (const auto& [leg, side] : {std::pair{m.left_leg, 1.0}, std::pair{m.right_leg, -1.0}}) {
        QVERIFY2(leg.direction.y() < -0.95 && side * leg.origin.x() > 0.03, qPrintable(what));
        QVERIFY2(std::abs(leg.length - (m.crotch - m.floor)) < 0.05, qPrintable(what));
      }
    }
  }

  void json_file_next_to_the_body_overrides() {
    QTemporaryDir folder;
    const std::filesystem::path obj = std::filesystem::path(folder.path().toStdString()) / "b.obj";
    std::filesystem::copy_file(default_body_path(), obj);
    SignedDistanceOptions options;
    options.spacing = 0.02;
    const Body derived = load_body(obj, options);
    QVERIFY(derived.overrides_file.empty());

    std::ofstream(location_overrides_path(obj)) << R"({
      "landmarks": {"waist": 1.05},
      "locations": [{"name": "neck", "radius": 0.09, "center": [0, 1.5, 0.01]}]
    })";
    const Body overridden = load_body(obj, options);
    QCOMPARE(overridden.overrides_file, location_overrides_path(obj));
    QCOMPARE(overridden.landmarks.waist, 1.05);
    // Locations derived from the moved landmark, then the given fields replaced.
    // (the plane's normal leans with the torso, so its centre is not exactly at that height)
    QVERIFY(std::abs(overridden.location("waist_front").center.y() - 1.05) < 0.015);
    QVERIFY(std::abs(derived.location("waist_front").center.y() - 1.05) > 0.05);
    QCOMPARE(overridden.location("neck").radius, 0.09);
    QVERIFY(overridden.location("neck").center.isApprox(Eigen::Vector3d(0, 1.5, 0.01)));
    QVERIFY(overridden.location("neck").axis.isApprox(derived.location("neck").axis));
    QVERIFY(
        overridden.location("neck_front").center.isApprox(derived.location("neck_front").center));
  }

  void bad_override_files_name_file_and_place_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    QTest::newRow("syntax") << "{\"landmarks\": "
                            << "not valid JSON";
    QTest::newRow("unknown location") << R"({"locations": [{"name": "knee"}]})"
                                      << "locations[0]: unknown location 'knee'";
    QTest::newRow("zero axis") << R"({"locations": [{"name": "neck", "axis": [0, 0, 0]}]})"
                               << "locations[0].axis: a direction cannot be zero";
    QTest::newRow("negative radius") << R"({"locations": [{"name": "neck", "radius": -1}]})"
                                     << "locations[0].radius: must be positive";
    QTest::newRow("bad surface") << R"({"locations": [{"name": "neck", "surface": "cone"}]})"
                                 << "locations[0].surface";
    QTest::newRow("unknown landmark") << R"({"landmarks": {"knee": 0.5}})"
                                      << "unknown landmark 'knee'";
    QTest::newRow("typo key") << R"({"location": []})"
                              << "unknown key 'location'";
    QTest::newRow("axis incomplete") << R"({"axes": {"torso": {"origin": [0, 1, 0]}}})"
                                     << "axes.torso: an axis needs origin, direction and length";
  }
  void bad_override_files_name_file_and_place() {
    QFETCH(QString, text);
    QFETCH(QString, expected);
    QTemporaryDir folder;
    const std::filesystem::path file =
        std::filesystem::path(folder.path().toStdString()) / "b.locations.json";
    std::ofstream(file) << text.toStdString();
    try {
      read_location_overrides(file);
      QFAIL("accepted a bad override file");
    } catch (const InputError& error) {
      const QString message = QString::fromStdString(error.what());
      QVERIFY2(message.startsWith(QString::fromStdString(file.string())), qPrintable(message));
      QVERIFY2(message.contains(expected), qPrintable(message));
    }
  }

  void a_shape_that_is_not_a_body_is_refused() {
    const BodyMesh cube = load_body_obj(test::test_data("bodies/cube_cm_inside_out.obj"));
    try {
      find_body_landmarks(cube, BodySlicer(cube));
      QFAIL("found landmarks on a cube");
    } catch (const InputError& error) {
      QVERIFY(QString(error.what()).contains("cube_cm_inside_out.obj"));
      QVERIFY(QString(error.what()).contains("not a human body in A-pose"));
    }
  }
};

QTEST_GUILESS_MAIN(BodyLocationsTest)
#include "test_locations.moc"
