// Exports never destroy work (issue 9, item 4): the garment OBJ export goes through
// write_file_atomically (temporary file + rename); it refuses to overwrite the input pattern (also
// under another name: a hard link); and an export that fails part-way — the writer throws, or the
// disk refuses more bytes (RLIMIT_FSIZE, as a full disk) — leaves the previous file byte for byte
// and no temporary file behind.

#include <QtTest>

#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/io/garment_obj.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/flat_placement.h"
#include "support/garment_init_process.h"
#include "support/test_paths.h"

using namespace garment;
namespace fs = std::filesystem;

namespace {

int entries(const fs::path& folder) {
  int count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder))
    ++count;
  return count;
}

// Lowers the file size limit for the scope (writes past it fail with EFBIG, SIGXFSZ ignored).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
  }

 private:
  rlimit saved_{};
  void (*previous_handler_)(int) = nullptr;
};

}  // namespace

class ExportsTest : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    folder_ = std::make_unique<QTemporaryDir>();  // a fresh folder per test function and row
    QVERIFY(folder_->isValid());
    dir_ = fs::path(folder_->path().toStdString());
    // The pattern is a copy in the test's folder: the test may try to overwrite it.
    pattern_path_ = dir_ / "pattern.json";
    fs::copy_file(test::test_data("energy/two_rectangles.json"), pattern_path_);
    garment_ = build_garment(load_pattern(pattern_path_));
    positions_ = Eigen::MatrixX3d::Zero(garment_.vertex_count(), 3);
    positions_.leftCols<2>() = garment_.rest_positions;
  }

  void exportWritesAFile() {
    const fs::path out = dir_ / "garment.obj";
    write_garment_obj(out, garment_, positions_);
    QCOMPARE(test::file_contents(out), format_garment_obj(garment_, positions_));
    QCOMPARE(read_garment_obj(out, garment_).rows(), garment_.vertex_count());
    QCOMPARE(entries(dir_), 2);  // pattern.json, garment.obj: no temporary left
  }

  void neverOverwritesTheInputPattern() {
    const std::string before = test::file_contents(pattern_path_);
    fs::create_hard_link(pattern_path_, dir_ / "same_file.obj");
    for (const fs::path& target :
         {pattern_path_, dir_ / "same_file.obj", dir_ / "." / "pattern.json"}) {
      try {
        write_garment_obj(target, garment_, positions_);
        QFAIL(qPrintable("overwrote the input pattern through " + QString::fromStdString(target)));
      } catch (const std::runtime_error& error) {
        const QString message = error.what();
        QVERIFY2(message.contains("input file") && message.contains("never overwritten"),
                 qPrintable(message));
        QVERIFY2(message.startsWith(QString::fromStdString(target.string())), qPrintable(message));
      }
      QCOMPARE(test::file_contents(pattern_path_), before);
    }
    QCOMPARE(entries(dir_), 2);
  }

  void failedExportKeepsThePreviousFile_data() {
    QTest::addColumn<QString>("failure");
    QTest::newRow("writer throws part-way") << "throw";
    QTest::newRow("disk refuses bytes (file size limit)") << "disk";
    QTest::newRow("positions of the wrong size") << "positions";
  }

  void failedExportKeepsThePreviousFile() {
    QFETCH(QString, failure);
    const fs::path out = dir_ / "garment.obj";
    write_garment_obj(out, garment_, positions_);
    const std::string previous = test::file_contents(out);
    QVERIFY(previous.size() > 4096);

    Eigen::MatrixX3d moved = positions_;
    moved.col(2).array() += 0.5;
    bool failed = false;
    try {
      if (failure == "throw") {
        write_file_atomically(out, [&](std::ostream& stream) {
          const std::string text = format_garment_obj(garment_, moved);
          stream.write(text.data(), static_cast<std::streamsize>(text.size() / 2));
          throw std::runtime_error("simulated failure half-way");
        });
      } else if (failure == "disk") {
        const FileSizeLimit limit(1024);
        write_garment_obj(out, garment_, moved);
      } else {
        write_garment_obj(out, garment_, Eigen::MatrixX3d::Zero(3, 3));
      }
    } catch (const std::exception& error) {
      failed = true;
      qInfo("%s", error.what());
    }
    QVERIFY2(failed, "the failing export did not report a failure");
    QCOMPARE(test::file_contents(out), previous);
    QCOMPARE(entries(dir_), 2);  // no temporary file left
  }

  void flatExportMatchesInMemory() {
    // The export that garment-init flat writes: re-reading it gives the positions back.
    const Eigen::MatrixX3d flat = flat_placement(garment_);
    const fs::path out = dir_ / "flat.obj";
    write_garment_obj(out, garment_, flat);
    QVERIFY((read_garment_obj(out, garment_) - flat).cwiseAbs().maxCoeff() < 1e-6);
  }

 private:
  std::unique_ptr<QTemporaryDir> folder_;
  fs::path dir_, pattern_path_;
  Garment garment_;
  Eigen::MatrixX3d positions_;
};

QTEST_GUILESS_MAIN(ExportsTest)
#include "test_exports.moc"
