// garment-init inspect lists the openings of the sewn garment with their rest lengths, in the
// text report and the JSON one. On Garment-Pattern-Generator's skirt with a waistband (two
// 66.7 cm wide panels sewn at the sides, gathered into a waistband of two 30 cm pieces) they are
// the waistband's top edge, 60 cm, and the hem, 133.3 cm: the numbers of the pattern file.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

#include "support/test_paths.h"

class InspectCommandTest : public QObject {
  Q_OBJECT

  const QString pattern_ = QString::fromStdString(
      garment::test::test_data("seeding/pattern_generator_templates/skirts__skirt_waistband.json")
          .string());

  static QByteArray run(const QStringList& arguments) {
    QProcess process;
    process.start(GARMENT_INIT_EXE, arguments);
    if (!process.waitForFinished(30000) || process.exitCode() != 0) return {};
    return process.readAllStandardOutput();
  }

 private slots:
  void json_lists_the_openings_with_their_rest_lengths() {
    const QByteArray out = run({"inspect", "--json", pattern_});
    QVERIFY(!out.isEmpty());
    std::map<QStringList, double> found;
    for (const QJsonValue& value : QJsonDocument::fromJson(out).object()["openings"].toArray()) {
      QStringList pieces;
      for (const QJsonValue& piece : value.toObject()["pieces"].toArray())
        pieces << piece.toString();
      pieces.sort();
      found[pieces] = value.toObject()["rest_length_m"].toDouble();
    }
    QCOMPARE(found.size(), std::size_t(2));
    const QStringList waistband{"wb_back", "wb_front"}, hem{"back", "front"};
    QVERIFY(found.count(waistband) && found.count(hem));
    qInfo("waistband %.4f m, hem %.4f m", found[waistband], found[hem]);
    QVERIFY(std::abs(found[waistband] - 0.60) < 1e-6);
    QVERIFY(std::abs(found[hem] - 2 * 0.6666666666666666) < 1e-6);
  }

  void text_report_prints_them_in_centimetres() {
    const QString out = QString::fromUtf8(run({"inspect", pattern_}));
    QVERIFY2(out.contains("openings when sewn"), qPrintable(out));
    QVERIFY2(out.contains(QRegularExpression(R"(\n\s+60\.0 cm\s+wb_back wb_front\n)")),
             qPrintable(out));
    QVERIFY2(out.contains(QRegularExpression(R"(\n\s+133\.3 cm\s+back front\n)")), qPrintable(out));
  }
};

QTEST_GUILESS_MAIN(InspectCommandTest)
#include "test_inspect_command.moc"
