// `garment-init run` writes the garment of the attempt the recovery chose (run_command.cpp): after
// a remesh that garment has its own mesh, and the OBJ and the report must be of it, not of the
// first pass's mesh. gc_0477 on f_smpl_average_A40 on one thread (judging half, a fixed case; see
// test_recovery.cpp): its first pass fails and a remesh rescues it.
// - with --attempts 1 the OBJ and the report have the first pass's vertices and the verdict fails;
// - by default the report's chosen attempt is a remesh, the verdict passes, and the OBJ's vertices
//   are as many as the report says and not as many as the first pass's.

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/test_environment.h"
#include "support/test_paths.h"

namespace {

int obj_vertex_count(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  int count = 0;
  while (std::getline(in, line))
    if (line.rfind("v ", 0) == 0) ++count;
  return count;
}

struct Run {
  int exit_code = -1;
  nlohmann::json report;
  int obj_vertices = 0;
};

Run run_gc_0477(const QTemporaryDir& dir, const QString& name, const QStringList& extra) {
  const QString obj = dir.filePath(name + ".obj");
  const QString report = dir.filePath(name + ".json");
  QProcess process;
  QStringList args = {
      "run",
      QString::fromStdString(
          garment::test::test_data("patterns/recovery/gc_0477_specification.json").string()),
      "--body",
      QString::fromStdString(garment::test::test_data("bodies/f_smpl_average_A40.obj").string()),
      "-o",
      obj,
      "--report",
      report,
      "--threads",
      "1",
      "--quiet"};
  args += extra;
  process.start(GARMENT_INIT_EXE, args);
  Run run;
  if (!process.waitForFinished(600000)) return run;
  run.exit_code = process.exitCode();
  std::ifstream in(report.toStdString());
  run.report = nlohmann::json::parse(in, nullptr, false);
  run.obj_vertices = obj_vertex_count(obj.toStdString());
  return run;
}

}  // namespace

class ChosenOutputsTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    if (garment::test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
  }

  void aRemeshedGarmentIsTheOneWritten() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const Run first = run_gc_0477(dir, "first", {"--attempts", "1"});
    QCOMPARE(first.exit_code, 3);  // written, the verdict failed
    QVERIFY(first.report.is_object());
    const int first_vertices = first.report.value("vertices", 0);
    QVERIFY(first_vertices > 0);
    QCOMPARE(first.obj_vertices, first_vertices);

    const Run recovered = run_gc_0477(dir, "recovered", {});
    QCOMPARE(recovered.exit_code, 0);
    QVERIFY(recovered.report.is_object());
    const nlohmann::json& recovery = recovered.report["recovery"];
    const int chosen = recovery.value("chosen", 0);
    QVERIFY(chosen > 0);
    QCOMPARE(recovery["attempts"][chosen].value("action", std::string()), std::string("remesh"));
    const int vertices = recovered.report.value("vertices", 0);
    QCOMPARE(recovered.obj_vertices, vertices);
    QVERIFY(vertices != first_vertices);
  }
};

QTEST_GUILESS_MAIN(ChosenOutputsTest)
#include "test_chosen_outputs.moc"
