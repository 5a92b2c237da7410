// `garment-init seed`: the classification report of a pattern, as JSON and as text, and a clear
// error for missing weights.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

#include "support/test_paths.h"

namespace {

struct Run {
  int exit_code = -1;
  QByteArray out, err;
};

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
    QVERIFY(!root.contains("seed"));  // no seed choice yet: nothing invented
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
  }
};

QTEST_APPLESS_MAIN(SeedCommandTest)
#include "test_seed_command.moc"
