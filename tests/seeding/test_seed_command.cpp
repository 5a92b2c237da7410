// `garment-init seed`: the classification report of a pattern and its seed, as JSON and as text;
// the manual override and its errors; -o writes the shaped seed; a clear error for missing weights.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "support/test_paths.h"

namespace {

struct Run {
  int exit_code = -1;
  QByteArray out, err;
};

QString pattern() {
  return QString::fromStdString(
      garment::test::test_data("patterns/gc_0012_specification.json").string());
}

Run run(const QStringList& arguments) {
  QProcess process;
  process.start(GARMENT_INIT_EXE, arguments);
  process.waitForFinished(120000);
  return {process.exitCode(), process.readAllStandardOutput(), process.readAllStandardError()};
}

}  // namespace

class SeedCommandTest : public QObject {
  Q_OBJECT
 private slots:
  void jsonReport() {
    const QString pattern = QString::fromStdString(
        garment::test::test_data("patterns/gc_0012_specification.json").string());
    const Run result = run({"seed", pattern, "--json"});
    QCOMPARE(result.exit_code, 0);
    const QJsonObject root = QJsonDocument::fromJson(result.out).object();
    const QJsonArray pieces = root["pieces"].toArray();
    QCOMPARE(pieces.size(), 4);  // skirt_front, skirt_back, wb_front, wb_back
    const QStringList classes = {"neck",         "waist",       "front_chest", "back_chest",
                                 "front_pelvis", "back_pelvis", "other"};
    QMap<QString, QString> class_of;
    for (const auto& value : pieces) {
      const QJsonObject piece = value.toObject();
      QVERIFY(classes.contains(piece["class"].toString()));
      const QJsonObject probabilities = piece["probabilities"].toObject();
      QCOMPARE(probabilities.size(), 7);
      double total = 0.0, best = 0.0;
      QString most_likely;
      for (const QString& name : classes) {
        const double p = probabilities[name].toDouble();
        total += p;
        if (p > best) best = p, most_likely = name;
      }
      QVERIFY(std::abs(total - 1.0) < 1e-9);
      QCOMPARE(piece["class"].toString(), most_likely);
      class_of[piece["name"].toString()] = piece["class"].toString();
    }
    QCOMPARE(class_of["wb_front"], QString("waist"));
    QCOMPARE(class_of["wb_back"], QString("waist"));
    const QJsonArray merged = root["waist_merge"].toArray();
    QCOMPARE(merged.size(), 1);
    QCOMPARE(merged[0].toArray().size(), 2);
    // The seed: the merged waistband, around the waist.
    const QJsonObject seed = root["seed"].toObject();
    QStringList seed_pieces;
    for (const auto& name : seed["pieces"].toArray())
      seed_pieces << name.toString();
    seed_pieces.sort();
    QCOMPARE(seed_pieces, QStringList({"wb_back", "wb_front"}));
    QCOMPARE(seed["location"].toString(), QString("waist"));
    QCOMPARE(seed["parts"].toArray().size(), 1);
    QCOMPARE(seed["manual"].toBool(), false);
    QVERIFY(!seed["reason"].toString().isEmpty());
  }

  void manualSeed() {
    const Run result = run({"seed", pattern(), "--json", "--seed-pieces", "skirt_front,skirt_back",
                            "--seed-location", "pelvis"});
    QCOMPARE(result.exit_code, 0);
    const QJsonObject seed = QJsonDocument::fromJson(result.out).object()["seed"].toObject();
    QCOMPARE(seed["pieces"].toArray().size(), 2);
    QCOMPARE(seed["pieces"].toArray()[0].toString(), QString("skirt_front"));
    QCOMPARE(seed["pieces"].toArray()[1].toString(), QString("skirt_back"));
    QCOMPARE(seed["location"].toString(), QString("pelvis"));
    QCOMPARE(seed["manual"].toBool(), true);
  }

  void manualSeedErrors() {
    // An unknown piece or location is bad input naming it; one option without the other is usage.
    Run result = run(
        {"seed", pattern(), "--seed-pieces", "wb_front,no_such_panel", "--seed-location", "waist"});
    QCOMPARE(result.exit_code, 1);
    QVERIFY2(result.err.contains("no_such_panel"), result.err.constData());
    result = run({"seed", pattern(), "--seed-pieces", "wb_front", "--seed-location", "elbow"});
    QCOMPARE(result.exit_code, 1);
    QVERIFY2(result.err.contains("elbow"), result.err.constData());
    QCOMPARE(run({"seed", pattern(), "--seed-pieces", "wb_front"}).exit_code, 2);
    QCOMPARE(run({"seed", pattern(), "--seed-location", "waist"}).exit_code, 2);
  }

  void writesShapedSeed() {
    QTemporaryDir out;
    const QString obj = out.filePath("seed.obj");
    const Run result = run({"seed", pattern(), "-o", obj});
    QCOMPARE(result.exit_code, 0);
    QVERIFY2(result.out.contains("wrote"), result.out.constData());
    QFile file(obj);
    QVERIFY(file.open(QIODevice::ReadOnly));
    // Only the seed's groups; every face indexes the file's own v/vt; the waistband sits at the
    // bundled body's waist (about 1.0-1.2 m up) and around it (both sides of x = 0, z = 0).
    QStringList groups;
    int vertices = 0, uvs = 0;
    double low = 1e9, high = -1e9, min_x = 1e9, max_x = -1e9, min_z = 1e9, max_z = -1e9;
    bool faces_in_range = true;
    int faces = 0;
    for (const QByteArray& line : file.readAll().split('\n')) {
      const QList<QByteArray> words = line.simplified().split(' ');
      if (words[0] == "g") groups << QString(words[1]);
      if (words[0] == "v") {
        ++vertices;
        const double x = words[1].toDouble(), y = words[2].toDouble(), z = words[3].toDouble();
        low = std::min(low, y), high = std::max(high, y);
        min_x = std::min(min_x, x), max_x = std::max(max_x, x);
        min_z = std::min(min_z, z), max_z = std::max(max_z, z);
      }
      if (words[0] == "vt") ++uvs;
      if (words[0] == "f") {
        ++faces;
        for (int k = 1; k < words.size(); ++k) {
          const QList<QByteArray> corner = words[k].split('/');
          const int v = corner[0].toInt(), vt = corner[1].toInt();
          faces_in_range = faces_in_range && v >= 1 && v <= vertices && vt >= 1 && vt <= uvs;
        }
      }
    }
    groups.sort();
    QCOMPARE(groups, QStringList({"wb_back", "wb_front"}));
    QVERIFY(vertices > 20 && vertices == uvs && faces > 20);
    QVERIFY(faces_in_range);
    QVERIFY2(low > 0.9 && high < 1.3, qPrintable(QString("y from %1 to %2").arg(low).arg(high)));
    QVERIFY(min_x < -0.1 && max_x > 0.1 && min_z < -0.05 && max_z > 0.05);
  }

  void writesManualSeedOnAGivenBody() {
    QTemporaryDir out;
    const QString obj = out.filePath("seed.obj");
    const Run result = run(
        {"seed", pattern(), "--body",
         QString::fromStdString(garment::test::test_data("bodies/f_smpl_average_A40.obj").string()),
         "--seed-pieces", "skirt_front", "--seed-location", "pelvis_front", "-o", obj, "--json"});
    QCOMPARE(result.exit_code, 0);
    QCOMPARE(QJsonDocument::fromJson(result.out).object()["seed"].toObject()["location"].toString(),
             QString("pelvis_front"));
    QFile file(obj);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    QVERIFY(text.contains("g skirt_front\n"));
    QVERIFY(!text.contains("g skirt_back") && !text.contains("g wb_"));
  }

  void badBodyIsBadInput() {
    QTemporaryDir out;
    const Run result =
        run({"seed", pattern(), "--body", "/nonexistent/body.obj", "-o", out.filePath("seed.obj")});
    QCOMPARE(result.exit_code, 1);
    QVERIFY2(result.err.contains("/nonexistent/body.obj"), result.err.constData());
    QVERIFY(!QFile::exists(out.filePath("seed.obj")));
  }

  void textReport() {
    const QString pattern = QString::fromStdString(
        garment::test::test_data("patterns/gc_0012_specification.json").string());
    const Run result = run({"seed", pattern});
    QCOMPARE(result.exit_code, 0);
    QVERIFY2(result.out.contains("waist merge: wb_front+wb_back") ||
                 result.out.contains("waist merge: wb_back+wb_front"),
             result.out.constData());
    QVERIFY(result.out.contains("wb_front"));
  }

  void missingWeightsIsBadInput() {
    const QString pattern = QString::fromStdString(
        garment::test::test_data("patterns/gc_0012_specification.json").string());
    const Run result = run({"seed", pattern, "--weights", "/nonexistent/weights.json"});
    QCOMPARE(result.exit_code, 1);
    QVERIFY2(result.err.contains("/nonexistent/weights.json"), result.err.constData());
  }

  void badUsage() {
    QCOMPARE(run({"seed"}).exit_code, 2);
    QCOMPARE(run({"seed", "a.json", "--no-such-option"}).exit_code, 2);
    QCOMPARE(run({"seed", "a.json", "-o"}).exit_code, 2);
  }
};

QTEST_APPLESS_MAIN(SeedCommandTest)
#include "test_seed_command.moc"
