// Every class of bad pattern input is rejected with one message that names the file and the place,
// both through the engine API (InputError) and the command line (exit status 1, message on stderr).

#include <QProcess>
#include <QtTest>

#include "engine/core/error.h"
#include "engine/pattern/garment_mesh.h"
#include "support/test_paths.h"

using namespace garment;

class PatternErrorsTest : public QObject {
  Q_OBJECT
 private slots:
  void rejectsBadInput_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("expected");  // fragments the message must contain
    QTest::newRow("invalid JSON") << "invalid_json.json"
                                  << QStringList{"line 1, column", "invalid JSON"};
    QTest::newRow("truncated JSON") << "truncated.json" << QStringList{"line ", "truncated JSON"};
    QTest::newRow("empty file") << "empty_file.json" << QStringList{"empty"};
    QTest::newRow("missing key") << "missing_key.json"
                                 << QStringList{"panel 'skirt_front'", "missing key \"edges\""};
    QTest::newRow("wrong type") << "wrong_type.json"
                                << QStringList{"panel 'skirt_front'",
                                               "\"vertices\" must be an array"};
    QTest::newRow("dangling panel")
        << "dangling_panel.json" << QStringList{"stitch 1", "'no_such_panel' does not exist"};
    QTest::newRow("dangling edge")
        << "dangling_edge.json" << QStringList{"stitch 2", "edge 99 does not exist"};
    QTest::newRow("vertex out of range")
        << "vertex_out_of_range.json"
        << QStringList{"panel 'skirt_front', edge 3", "vertex index 99 out of range"};
    QTest::newRow("open loop") << "open_loop.json"
                               << QStringList{"panel 'skirt_front', edge 2", "closed loop"};
    QTest::newRow("edge in two stitches")
        << "edge_in_two_stitches.json" << QStringList{"stitch 8", "already sewn by stitch 0"};
    QTest::newRow("zero-length edge")
        << "zero_length_edge.json" << QStringList{"panel 'skirt_front', edge 1", "zero length"};
    QTest::newRow("self-intersecting outline")
        << "self_intersecting.json"
        << QStringList{"panel 'bowtie', edge 1 and edge 3", "intersects itself"};
    // Its edge 0 (vertices 0 to 1) crosses edges 2 and 3; it was refused as "edges 0 and 0: the
    // outline is too narrow to mesh".
    QTest::newRow("self-intersecting pentagram")
        << "pentagram.json" << QStringList{"panel 'star', edge 0 and edge 2", "intersects itself"};
    // A 3-4-5 mm triangle: the 5 mm edge stays, the 3 mm one merges, the 4 mm one would take the
    // run to 7 mm, over a quarter of 20 mm, and stays: two points, no polygon.
    QTest::newRow("panel under the mesh resolution")
        << "tiny_panel.json"
        << QStringList{"panel 'tiny'",
                       "smaller than the mesh resolution: 12 mm round, it leaves "
                       "2 point(s) at 20 mm"};
    QTest::newRow("non-finite number")
        << "non_finite.json" << QStringList{"line 21", "out of range"};
    QTest::newRow("unknown curvature")
        << "unknown_curvature.json"
        << QStringList{"panel 'skirt_front', edge", "unknown curvature type \"spline\""};
    QTest::newRow("empty pattern") << "empty_pattern.json" << QStringList{"no panels"};
  }

  void rejectsBadInput() {
    QFETCH(QString, file);
    QFETCH(QStringList, expected);
    const std::filesystem::path path = test::test_data("patterns/bad") / file.toStdString();
    QVERIFY(std::filesystem::exists(path));
    try {
      build_garment(load_pattern(path));
      QFAIL("accepted a bad pattern");
    } catch (const InputError& error) {
      const QString message = QString::fromStdString(error.what());
      QVERIFY2(message.startsWith(QString::fromStdString(path.string())), qPrintable(message));
      for (const QString& fragment : expected)
        QVERIFY2(message.contains(fragment), qPrintable(message));
    }

    QProcess process;
    process.start(GARMENT_INIT_EXE, {"inspect", QString::fromStdString(path.string())});
    QVERIFY(process.waitForFinished(30000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QCOMPARE(process.exitCode(), 1);
    const QString message = QString::fromUtf8(process.readAllStandardError());
    QVERIFY2(message.count('\n') == 1, qPrintable(message));  // one clear message
    for (const QString& fragment : expected)
      QVERIFY2(message.contains(fragment), qPrintable(message));
  }

  void usageErrorsExitTwo() {
    for (const QStringList& arguments :
         {QStringList{}, QStringList{"inspect"}, QStringList{"inspect", "a", "b"},
          QStringList{"inspect", "x.json", "--no-such-option"}, QStringList{"frobnicate"}}) {
      QProcess process;
      process.start(GARMENT_INIT_EXE, arguments);
      QVERIFY(process.waitForFinished(30000));
      QCOMPARE(process.exitCode(), 2);
    }
  }

  void helpDocumentsEveryCommand() {
    QProcess process;
    process.start(GARMENT_INIT_EXE, {"--help"});
    QVERIFY(process.waitForFinished(30000));
    QCOMPARE(process.exitCode(), 0);
    QVERIFY(QString::fromUtf8(process.readAllStandardOutput()).contains("inspect PATTERN.json"));
  }

  void vertexBudgetRefusesHugeMeshes() {
    const Pattern pattern = load_pattern(test::test_data("patterns/gc_0000_specification.json"));
    MeshingOptions options;
    options.target_edge_length = 0.0005;
    options.vertex_budget = 100000;
    QVERIFY_THROWS_EXCEPTION(BudgetError, build_garment(pattern, options));
  }
};

QTEST_APPLESS_MAIN(PatternErrorsTest)
#include "test_pattern_errors.moc"
