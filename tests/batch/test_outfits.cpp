// Outfits on the command line (issue "Complex garments"): `batch --outfits LIST` runs an outfit per
// line of a list file through `run` with several patterns, and `check --pattern a,b` measures the
// outfit it wrote. Real patterns (tests/data: gc_0022, a sleeveless top, and gc_0340, a maxi
// pencil skirt, both made for f_smpl_average_A40, tuning half), the top tucked in:
// - the outfit's OBJ has every piece of both garments, grouped GARMENT:PANEL, the top's first;
// - its report lists both garments in order with their seeds, and no crossing between them;
// - the summary names the outfit by its garments joined with '+';
// - `check` with the two patterns judges the OBJ as `run` did (clean);
// - a list naming a missing pattern is refused, naming the list's line, before any work.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/garment_init_process.h"
#include "support/test_paths.h"

namespace fs = std::filesystem;

namespace {

using garment::test::file_contents;
using garment::test::garment_init;
using garment::test::ProcessResult;

QJsonObject json_file(const fs::path& path) {
  return QJsonDocument::fromJson(QByteArray::fromStdString(file_contents(path))).object();
}

QString data(const char* relative) {
  return QString::fromStdString(garment::test::test_data(relative).string());
}

}  // namespace

class OutfitCommandsTest : public QObject {
  Q_OBJECT
 private slots:
  void batchRunsAnOutfitPerLine() {
    QTemporaryDir work;
    QVERIFY(work.isValid());
    const fs::path list = fs::path(work.path().toStdString()) / "outfits.txt";
    std::ofstream(list) << "# the top tucked in\n\n"
                        << data("patterns/gc_0022_specification.json").toStdString() << " "
                        << data("patterns/gc_0340_specification.json").toStdString() << " "
                        << data("bodies/f_smpl_average_A40.obj").toStdString() << "\n";
    const QString out = work.path() + "/out";
    const ProcessResult batch = garment_init(
        {"batch", "--outfits", QString::fromStdString(list.string()), "-o", out, "--jobs", "1"});
    QVERIFY2(batch.exit_code == 0, qPrintable(batch.err));

    const QJsonArray results =
        json_file((out + "/summary.json").toStdString())["results"].toArray();
    QCOMPARE(results.size(), 1);
    QCOMPARE(results[0].toObject()["name"].toString(), QString("gc_0022+gc_0340"));
    QCOMPARE(results[0].toObject()["status"].toString(), QString("ok"));

    const QJsonObject report = json_file((out + "/gc_0022+gc_0340.report.json").toStdString());
    const QJsonArray garments = report["outfit"].toObject()["garments"].toArray();
    QCOMPARE(garments.size(), 2);
    QCOMPARE(garments[0].toObject()["name"].toString(), QString("gc_0022"));
    QCOMPARE(garments[1].toObject()["name"].toString(), QString("gc_0340"));
    for (const QJsonValue& garment : garments)
      QVERIFY(!garment.toObject()["seed"].toObject()["parts"].toArray().isEmpty());
    QVERIFY(report["outfit"].toObject().contains("crossings_between_garments"));
    QVERIFY(report["outfit"].toObject()["crossings_between_garments"].toArray().isEmpty());

    // Groups: the top's pieces, then the skirt's, each named GARMENT:PANEL.
    std::istringstream obj(file_contents((out + "/gc_0022+gc_0340.obj").toStdString()));
    std::string line;
    int top = 0, skirt = 0;
    while (std::getline(obj, line)) {
      if (line.rfind("g ", 0) != 0) continue;
      if (line.rfind("g gc_0022:", 0) == 0) {
        QCOMPARE(skirt, 0);
        ++top;
      } else {
        QVERIFY2(line.rfind("g gc_0340:", 0) == 0, line.c_str());
        ++skirt;
      }
    }
    QVERIFY(top >= 2 && skirt >= 2);
    QCOMPARE(top + skirt, report["pieces"].toInt());

    const ProcessResult check = garment_init({"check", out + "/gc_0022+gc_0340.obj", "--pattern",
                                              data("patterns/gc_0022_specification.json") + "," +
                                                  data("patterns/gc_0340_specification.json"),
                                              "--body", data("bodies/f_smpl_average_A40.obj")});
    QVERIFY2(check.exit_code == 0, qPrintable(check.out + check.err));
    QVERIFY(check.out.contains("gc_0340_specification.json"));
  }

  void missingPatternIsRefusedWithItsLine() {
    QTemporaryDir work;
    QVERIFY(work.isValid());
    const fs::path list = fs::path(work.path().toStdString()) / "outfits.txt";
    std::ofstream(list) << data("patterns/gc_0022_specification.json").toStdString() << " "
                        << data("patterns/gc_0340_specification.json").toStdString() << "\n"
                        << data("patterns/gc_0022_specification.json").toStdString()
                        << " no_such_skirt.json\n";
    const QString out = work.path() + "/out";
    const ProcessResult batch =
        garment_init({"batch", "--outfits", QString::fromStdString(list.string()), "-o", out});
    QCOMPARE(batch.exit_code, 1);
    QVERIFY2(batch.err.contains("line 2") && batch.err.contains("no_such_skirt.json"),
             qPrintable(batch.err));
    QVERIFY(!QFileInfo::exists(out + "/summary.json"));
  }
};

QTEST_GUILESS_MAIN(OutfitCommandsTest)
#include "test_outfits.moc"
